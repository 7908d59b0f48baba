// SPDX-License-Identifier: MIT
namespace Frusta.Binding
{
    /// <summary>A force and torque (a wrench) seen about another point: a world's reaction torque is
    /// about the object's pose position, a physics engine takes it about the body's centre of mass.
    /// Pure functions: any thread, no allocation.</summary>
    public static class Wrench
    {
        /// <summary>The torque about <paramref name="to"/> of a wrench whose torque about
        /// <paramref name="from"/> is <paramref name="torque"/>: torque + (from - to) x force. The
        /// force itself is the same about any point.</summary>
        /// <param name="torque">Newton-metres, about <paramref name="from"/>.</param>
        /// <param name="force">Newtons, the wrench's total force.</param>
        /// <param name="from">The point the torque is about, metres.</param>
        /// <param name="to">The point wanted, metres (one frame with the others: Frusta's, or Unity's
        /// with the torque converted by <see cref="CoordinateConversion.AxialFromUnity"/>).</param>
        /// <returns>Newton-metres about <paramref name="to"/>.</returns>
        public static Vector3d TorqueAbout(Vector3d torque, Vector3d force, Vector3d from, Vector3d to) =>
            torque + Vector3d.Cross(from - to, force);
    }
}
