using System;

namespace HeadGait
{
    /// <summary>
    /// Accelerometer stand-in for headsets whose runtime reports the head pose but not its acceleration
    /// (common with OpenXR): the tracked position is differentiated twice (non-uniform central difference),
    /// gravity is added and the result is rotated into the head frame. Poses are in Unity's tracking space
    /// (x right, y up, z forward; rotation as a unit quaternion x, y, z, w). Each output belongs to the
    /// previous pose, so it arrives one frame late. Differentiation amplifies tracking noise: prefer a real
    /// accelerometer where the runtime has one.
    /// </summary>
    public sealed class PoseAccelerationEstimator
    {
        readonly double gravity;
        readonly double maxGap;
        readonly double[] t = new double[3];
        readonly double[,] p = new double[3, 3];
        readonly double[,] q = new double[3, 4];
        int count;

        public PoseAccelerationEstimator(double gravity = 9.80665, double maxGap = 0.1)
        {
            this.gravity = gravity;
            this.maxGap = maxGap;
        }

        public int Skipped { get; private set; }

        public void Reset() => count = 0;

        /// <summary>
        /// Adds a pose; returns true with the head-frame specific force at the previous pose's time once three
        /// poses are at hand. Non-finite values and non-increasing times are skipped; a hole over maxGap restarts.
        /// </summary>
        public bool Push(double time, double px, double py, double pz, double qx, double qy, double qz, double qw, out ImuSample sample)
        {
            sample = default;
            double qn = Math.Sqrt(qx * qx + qy * qy + qz * qz + qw * qw);
            if (!Finite(time) || !Finite(px) || !Finite(py) || !Finite(pz) || !Finite(qn) || qn < 1e-6)
            {
                Skipped++;
                return false;
            }
            if (count > 0)
            {
                double last = t[Math.Min(count, 3) - 1];
                if (!(time > last))
                {
                    Skipped++;
                    return false;
                }
                if (time - last > maxGap) count = 0;
            }
            if (count == 3)
            {
                for (int i = 0; i < 2; i++)
                {
                    t[i] = t[i + 1];
                    for (int k = 0; k < 3; k++) p[i, k] = p[i + 1, k];
                    for (int k = 0; k < 4; k++) q[i, k] = q[i + 1, k];
                }
                count = 2;
            }
            t[count] = time;
            p[count, 0] = px;
            p[count, 1] = py;
            p[count, 2] = pz;
            q[count, 0] = qx / qn;
            q[count, 1] = qy / qn;
            q[count, 2] = qz / qn;
            q[count, 3] = qw / qn;
            count++;
            if (count < 3) return false;

            double h0 = t[1] - t[0], h1 = t[2] - t[1];
            var a = new double[3];
            for (int k = 0; k < 3; k++)
                a[k] = 2.0 * ((p[2, k] - p[1, k]) / h1 - (p[1, k] - p[0, k]) / h0) / (h0 + h1);
            // Specific force in tracking space (Unity y is up), then into the head's local Unity axes.
            double fx = a[0], fy = a[1] + gravity, fz = a[2];
            RotateByInverse(q[1, 0], q[1, 1], q[1, 2], q[1, 3], ref fx, ref fy, ref fz);
            // Unity local (right, up, forward) -> head frame (forward, left, up).
            sample = new ImuSample(t[1], fz, -fx, fy);
            return true;
        }

        /// <summary>v := conj(q) v q, i.e. the inverse rotation of v by the unit quaternion q.</summary>
        static void RotateByInverse(double x, double y, double z, double w, ref double vx, ref double vy, ref double vz)
        {
            // Rotation by the conjugate (-x, -y, -z, w): v' = v + 2w' (u x v) + 2 u x (u x v), u = (-x, -y, -z), w' = w.
            double ux = -x, uy = -y, uz = -z;
            double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
            double ccx = uy * cz - uz * cy, ccy = uz * cx - ux * cz, ccz = ux * cy - uy * cx;
            vx += 2 * (w * cx + ccx);
            vy += 2 * (w * cy + ccy);
            vz += 2 * (w * cz + ccz);
        }

        static bool Finite(double v) => !double.IsNaN(v) && !double.IsInfinity(v);
    }
}
