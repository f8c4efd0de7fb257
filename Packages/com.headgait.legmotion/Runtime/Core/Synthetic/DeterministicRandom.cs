using System;

namespace HeadGait.Synthetic
{
    /// <summary>SplitMix64: the same sequence on every runtime (System.Random's is not guaranteed).</summary>
    public sealed class DeterministicRandom
    {
        ulong state;
        double spare;
        bool hasSpare;

        public DeterministicRandom(ulong seed)
        {
            state = seed;
        }

        /// <summary>
        /// A seed from a name (FNV-1a): the same on every runtime and independent of the order things are listed in, so a
        /// recording's augmentation or a participant's row depends on its name alone.
        /// </summary>
        public static ulong SeedFrom(string name)
        {
            ulong h = 1469598103934665603UL;
            foreach (char c in name ?? "")
            {
                h ^= c;
                h *= 1099511628211UL;
            }
            return h == 0 ? 1 : h;
        }

        public ulong NextULong()
        {
            ulong z = state += 0x9E3779B97F4A7C15UL;
            z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
            z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
            return z ^ (z >> 31);
        }

        /// <summary>Uniform in [0, 1).</summary>
        public double NextDouble() => (NextULong() >> 11) * (1.0 / 9007199254740992.0);

        public double Uniform(double min, double max) => min + (max - min) * NextDouble();

        /// <summary>Standard normal (Box-Muller).</summary>
        public double NextGaussian()
        {
            if (hasSpare)
            {
                hasSpare = false;
                return spare;
            }
            double u1 = 1.0 - NextDouble();
            double u2 = NextDouble();
            double r = Math.Sqrt(-2.0 * Math.Log(u1));
            spare = r * Math.Sin(2 * Math.PI * u2);
            hasSpare = true;
            return r * Math.Cos(2 * Math.PI * u2);
        }
    }
}
