using System;
using System.Diagnostics;

namespace HeadGait.Cli
{
    /// <summary>
    /// Progress of long work (train, benchmark, replay of many files) with an estimate of the time left, on standard error and
    /// only when it is a terminal: a CI log or a redirected run stays as quiet as before. One line, rewritten in place.
    /// </summary>
    sealed class Progress : IDisposable
    {
        readonly string what;
        readonly int total;
        readonly Stopwatch watch = Stopwatch.StartNew();
        readonly bool shown;
        int done;
        double lastShown = double.NegativeInfinity;

        public Progress(string what, int total)
        {
            this.what = what;
            this.total = Math.Max(1, total);
            shown = Enabled;
        }

        /// <summary>Standard error is a terminal and no CI is declared (CI=true, as GitHub Actions and most CI set).</summary>
        public static bool Enabled => !Console.IsErrorRedirected && Environment.GetEnvironmentVariable("CI") == null;

        /// <summary>One more part done; <paramref name="label"/> says which (shown beside the count).</summary>
        public void Step(string label = null)
        {
            done = Math.Min(total, done + 1);
            if (!shown) return;
            double elapsed = watch.Elapsed.TotalSeconds;
            if (done < total && elapsed - lastShown < 0.5) return; // at most twice a second
            lastShown = elapsed;
            double left = elapsed / done * (total - done);
            Console.Error.Write($"\r{what}: {done}/{total} ({100 * done / total} %), {Describe(elapsed)} so far, about {Describe(left)} left{(label != null ? " - " + label : "")}\u001b[K");
        }

        static string Describe(double seconds) => seconds >= 90 ? $"{seconds / 60:0} min" : $"{seconds:0} s";

        public void Dispose()
        {
            if (shown && done > 0) Console.Error.WriteLine();
        }
    }
}
