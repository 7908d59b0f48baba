# SPDX-License-Identifier: MIT
# gnuplot -e "trace='TRACE.csv'; image='TRACE.png'" samples/plot_trace.gp
# The demo's trace over time: the force on each finger, the deepest penetration, and
# the step time of the world's thread.
set datafile separator ","
set terminal pngcairo size 1200,900 font "sans,10"
set output image
set multiplot layout 3,1 title "Frusta demo: ".trace
set key outside right noenhanced
set grid
set xlabel "time (s)"
set ylabel "force (N)"
plot for [c=7:11] trace using 1:c with lines title columnheader(c), \
     trace using 1:12 with lines dashtype 2 title "palm"
set ylabel "penetration (mm)"
plot trace using 1:6 with lines title "deepest"
set ylabel "step time (us)"
set logscale y
plot trace using 1:3 with dots title "step"
unset multiplot
