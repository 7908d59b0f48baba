// SPDX-License-Identifier: MIT
using System;

namespace Frusta.Binding
{
    /// <summary>
    /// A bake running on a native thread of its own (<c>frusta_start_bake</c>), for an editor that shows
    /// its progress and lets the user cancel it: start it, read <see cref="Progress"/> and
    /// <see cref="IsDone"/> each editor update, <see cref="Cancel"/> on request, and <see cref="Finish"/>
    /// for the tree once done (Finish waits if it is not). The mesh is copied at the start. Disposing an
    /// unfinished job cancels it and throws its result away. Thread: any; one thread finishes a job.
    /// </summary>
    public sealed unsafe class BakeJob : IDisposable
    {
        readonly BakeJobHandle handle;

        BakeJob(BakeJobHandle handle) => this.handle = handle;

        /// <summary>Start baking as <see cref="SphereTree.Bake(ReadOnlySpan{float}, ReadOnlySpan{int}, in FrustaBakeDef)"/>
        /// bakes. The def's errors come from here; the mesh's from <see cref="Finish"/>.</summary>
        /// <param name="vertices">xyz triples, metres, right-handed object frame.</param>
        /// <param name="indices">Three per triangle, counter-clockwise seen from outside.</param>
        /// <param name="def">From <see cref="FrustaBakeDef.Default"/>, then edited.</param>
        /// <returns>The running job; finish or dispose it.</returns>
        /// <exception cref="FrustaException">A def value out of range.</exception>
        public static BakeJob Start(ReadOnlySpan<float> vertices, ReadOnlySpan<int> indices, in FrustaBakeDef def)
        {
            if (vertices.Length % 3 != 0) throw new ArgumentException("must hold xyz triples", nameof(vertices));
            FrustaLibrary.EnsureCompatible();
            var h = new BakeJobHandle();
            FrustaBakeJobId id;
            FrustaResult r;
            // pointers to something even for empty spans (their pointers are null): the bake
            // refuses the empty mesh by its counts
            float noVertex = 0;
            int noIndex = 0;
            fixed (float* v = vertices)
            fixed (int* i = indices)
            fixed (FrustaBakeDef* d = &def)
                r = Native.frusta_start_bake(v != null ? v : &noVertex, vertices.Length / 3, i != null ? i : &noIndex,
                                             indices.Length, d, &id);
            h.Own(r, id, "frusta_start_bake");
            return new BakeJob(h);
        }

        /// <summary>How far the bake has come, 0..1, never decreasing (<c>frusta_bake_job_progress</c>).</summary>
        public double Progress => Read(out _);

        /// <summary>true once the bake has ended (baked, failed or cancelled): <see cref="Finish"/> returns at once.</summary>
        public bool IsDone
        {
            get
            {
                Read(out bool done);
                return done;
            }
        }

        double Read(out bool done)
        {
            double fraction;
            int ended;
            using (new HandleUse(handle))
                Errors.Check(Native.frusta_bake_job_progress(handle.Id, &fraction, &ended), "frusta_bake_job_progress");
            done = ended != 0;
            return fraction;
        }

        /// <summary>Ask the bake to stop (<c>frusta_cancel_bake_job</c>): <see cref="Finish"/> then throws
        /// <see cref="FrustaResult.Cancelled"/>, even if the bake had ended.</summary>
        public void Cancel()
        {
            using (new HandleUse(handle))
                Errors.Check(Native.frusta_cancel_bake_job(handle.Id), "frusta_cancel_bake_job");
        }

        /// <summary>Wait for the bake to end and take its tree (<c>frusta_finish_bake_job</c>); the job is
        /// then spent (disposed).</summary>
        /// <returns>The tree; dispose it.</returns>
        /// <exception cref="FrustaException">The bake's error (a degenerate mesh, with the native
        /// message), or <see cref="FrustaResult.Cancelled"/>.</exception>
        public SphereTree Finish()
        {
            FrustaTreeId tree;
            FrustaResult r;
            using (new HandleUse(handle))
                r = Native.frusta_finish_bake_job(handle.Id, &tree);
            // finished natively whatever it said: nothing is left to cancel
            handle.SetHandleAsInvalid();
            return SphereTree.Own(r, tree, "frusta_finish_bake_job");
        }

        /// <summary>Cancel an unfinished job and throw its result away. Safe to call twice.</summary>
        public void Dispose() => handle.Dispose();
    }
}
