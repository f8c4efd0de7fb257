using System;

namespace HeadGait
{
    /// <summary>
    /// Accelerometer stand-in for headsets whose runtime reports the head pose but not its acceleration (OpenXR, most
    /// standalone headsets): the tracked position is differentiated twice, gravity added and the result rotated into the
    /// head frame. Poses are in Unity's tracking space (x right, y up, z forward; rotation a unit quaternion x, y, z, w
    /// mapping the camera's axes into it).
    /// <para>
    /// Tracking noise of half a millimetre becomes metres per second squared when differentiated twice over one frame,
    /// so the acceleration comes from a least-squares quadratic fitted to the positions of the last
    /// <see cref="WindowSeconds"/> (any frame rate, uneven frame times) and belongs to the middle of that window. Each
    /// sample is stamped with the newest pose's time, when it became known; <see cref="Lag"/> says how far behind that
    /// the motion it describes is, so the pipeline can look ahead by as much (<see cref="GaitPipeline.SourceLag"/>).
    /// </para>
    /// </summary>
    public sealed class PoseAccelerationEstimator
    {
        /// <summary>
        /// 120 ms: 0.5 mm of tracking noise becomes about 0.5 m/s^2 over an 85 ms fit and much less over 120 ms; in
        /// leave-one-style-out cross-validation COR on pose recordings went from 36.0 % to 30.0 % misclassification
        /// (28.9 % on the accelerometer recordings of the same clips), the longer lag being looked ahead by the pipeline.
        /// </summary>
        public const double DefaultWindowSeconds = 0.12;
        const int Capacity = 64;
        const double MaxSpanFactor = 1.15;

        readonly double gravity;
        readonly double maxGap;
        readonly double[] t = new double[Capacity];
        readonly double[,] p = new double[Capacity, 3];
        readonly double[,] q = new double[Capacity, 4];
        int count, head;
        int holesInARow;
        bool warned;
        string warning;

        public PoseAccelerationEstimator(double gravity = 9.80665, double maxGap = 0.1, double windowSeconds = DefaultWindowSeconds)
        {
            if (!(windowSeconds > 0 && windowSeconds < 1)) throw new ArgumentException("The fit window must be between 0 and 1 s.", nameof(windowSeconds));
            this.gravity = gravity;
            this.maxGap = maxGap;
            WindowSeconds = windowSeconds;
        }

        /// <summary>Span of poses each acceleration is fitted to (s).</summary>
        public double WindowSeconds { get; }

        public int Skipped { get; private set; }

        /// <summary>
        /// The lowest pose rate that gives samples (Hz): the fit needs five poses within <see cref="MaxSpanFactor"/> times
        /// <see cref="WindowSeconds"/> (about 29 Hz for the default 120 ms); slower poses give none, with a warning once.
        /// </summary>
        public double LowestRate => 4 / (MaxSpanFactor * WindowSeconds);

        /// <summary>A rate problem met since the last call, in words (once per estimator), or null.</summary>
        public string TakeWarning()
        {
            string w = warning;
            warning = null;
            return w;
        }

        void WarnTooSlow(double interval)
        {
            if (warned) return;
            warned = true;
            warning = string.Format(System.Globalization.CultureInfo.InvariantCulture,
                "poses come {0:G3} s apart ({1:G3} Hz), slower than the pose path's lowest rate of {2:G3} Hz: no acceleration can be fitted and the avatar stands",
                interval, 1 / interval, LowestRate);
        }

        /// <summary>How far the last sample's motion lies behind its timestamp (s): half the fit window, about 60 ms.</summary>
        public double Lag { get; private set; }

        public void Reset()
        {
            count = 0;
            head = 0;
        }

        int Index(int back) => (head - 1 - back + 2 * Capacity) % Capacity;

        /// <summary>
        /// Adds a pose; returns true with the head-frame specific force (x forward, y left, z up) once the poses span the
        /// fit window. Non-finite values, repeated times and late poses are skipped; a hole over maxGap or a clock that moved
        /// further back starts over.
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
                double last = t[Index(0)];
                if (time < last - PreprocessorSettings.DefaultBackwardTolerance || time - last > maxGap)
                {
                    // A hole, or a clock that restarted further back than a late pose: fit afresh from this pose.
                    if (time - last > maxGap && ++holesInARow >= 3) WarnTooSlow(time - last);
                    Reset();
                }
                else if (!(time > last))
                {
                    Skipped++;
                    return false;
                }
            }
            t[head] = time;
            p[head, 0] = px;
            p[head, 1] = py;
            p[head, 2] = pz;
            q[head, 0] = qx / qn;
            q[head, 1] = qy / qn;
            q[head, 2] = qz / qn;
            q[head, 3] = qw / qn;
            head = (head + 1) % Capacity;
            if (count < Capacity) count++;

            // The poses of the last WindowSeconds (at least five): an odd number, so one of them is the middle. An even
            // count takes one pose more where it stays near the window (at 60 Hz 9 poses span 133 ms, 7 only 100 ms).
            int n = 1;
            while (n < count && time - t[Index(n)] <= WindowSeconds + 1e-9) n++;
            if (n % 2 == 0) n = n < count && time - t[Index(n)] <= MaxSpanFactor * WindowSeconds ? n + 1 : n - 1;
            if (n < 5 && count >= 5) WarnTooSlow((time - t[Index(count - 1)]) / (count - 1)); // five poses held, too far apart to fit
            if (n < 5 || time - t[Index(n - 1)] < 0.5 * WindowSeconds) return false;
            holesInARow = 0;
            int centre = Index(n / 2);
            double tc = t[centre];
            // Least squares x(t) = a + b (t - tc) + c (t - tc)^2; the acceleration is 2c.
            double s0 = n, s1 = 0, s2 = 0, s3 = 0, s4 = 0;
            double y0x = 0, y1x = 0, y2x = 0, y0y = 0, y1y = 0, y2y = 0, y0z = 0, y1z = 0, y2z = 0;
            for (int k = 0; k < n; k++)
            {
                int i = Index(k);
                double d = t[i] - tc, d2 = d * d;
                s1 += d;
                s2 += d2;
                s3 += d2 * d;
                s4 += d2 * d2;
                y0x += p[i, 0]; y1x += p[i, 0] * d; y2x += p[i, 0] * d2;
                y0y += p[i, 1]; y1y += p[i, 1] * d; y2y += p[i, 1] * d2;
                y0z += p[i, 2]; y1z += p[i, 2] * d; y2z += p[i, 2] * d2;
            }
            // Cramer's rule for the quadratic coefficient of the 3x3 normal equations.
            double det = s0 * (s2 * s4 - s3 * s3) - s1 * (s1 * s4 - s3 * s2) + s2 * (s1 * s3 - s2 * s2);
            if (Math.Abs(det) < 1e-30) return false;
            double C(double y0, double y1, double y2) => (s0 * (s2 * y2 - s3 * y1) - s1 * (s1 * y2 - s3 * y0) + s2 * (s1 * y1 - s2 * y0)) / det;
            double ax = 2 * C(y0x, y1x, y2x), ay = 2 * C(y0y, y1y, y2y), az = 2 * C(y0z, y1z, y2z);
            // Specific force in tracking space (Unity y is up), then into the head's local Unity axes at the middle pose.
            double fx = ax, fy = ay + gravity, fz = az;
            RotateByInverse(q[centre, 0], q[centre, 1], q[centre, 2], q[centre, 3], ref fx, ref fy, ref fz);
            // Unity local (right, up, forward) -> head frame (forward, left, up).
            sample = new ImuSample(time, fz, -fx, fy);
            Lag = time - tc;
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
