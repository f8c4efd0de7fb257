using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace HeadGait.Cli
{
    /// <summary>The tables replay and benchmark print: phase accuracy, then steps and walking/standing, per classifier.</summary>
    static class Report
    {
        static string F(double v, string fmt) => double.IsNaN(v) ? "-" : v.ToString(fmt, CultureInfo.InvariantCulture);
        static string P(double v) => F(100 * v, "F1");

        const string PhaseFormat = "{0,-20} {1,-9} {2,6} {3,6} {4,6} {5,6} {6,5} {7,5} {8,5} {9,8} {10,8} {11,7} {12,5}";
        const string StepFormat = "{0,-20} {1,-9} {2,-6} {3,7} {4,6} {5,6} {6,6} {7,6} {8,6} {9,6} {10,6} {11,7} {12,6} {13,6}";

        public static void PhaseHeader()
        {
            string h = string.Format(CultureInfo.InvariantCulture, PhaseFormat, "recordings", "clf", "miscl%", "avat%", "adj%", "avadj%",
                "MAE", "MSE", "RMSE", "CEP25-95", "delay_ms", "ms/win", "skip");
            Console.WriteLine(h);
            Console.WriteLine(new string('-', h.Length));
        }

        public static void PhaseRow(string label, string classifier, IReadOnlyList<ReplayResult> results)
        {
            var c = GaitMetrics.Pool(results.Select(r => r.ClassifierMetrics));
            var a = GaitMetrics.Pool(results.Select(r => r.AnimatorMetrics));
            bool has = c.Comparisons > 0;
            Console.WriteLine(string.Format(CultureInfo.InvariantCulture, PhaseFormat, Trim(label, 20), classifier,
                has ? P(c.MisclassificationRate) : "-", has ? P(a.MisclassificationRate) : "-",
                has ? P(c.MisclassificationBeyondAdjacent) : "-", has ? P(a.MisclassificationBeyondAdjacent) : "-",
                has ? F(c.Mae, "F2") : "-", has ? F(c.Mse, "F2") : "-", has ? F(c.Rmse, "F2") : "-",
                has ? $"{c.Cep25:F0}/{c.Cep50:F0}/{c.Cep75:F0}/{c.Cep95:F0}" : "-",
                has ? F(c.MeanDelayMs, "F0") : "-", F(MsPerWindow(results), "F4"),
                results.Sum(r => r.SkippedSamples + r.FileWarnings)));
        }

        public static void StepHeader()
        {
            string h = string.Format(CultureInfo.InvariantCulture, StepFormat, "recordings", "clf", "output", "IC_ms", "IC_sd",
                "recall", "prec%", "foot%", "walk>st", "st>walk", "bouts", "start_s", "stop_s", "steps");
            Console.WriteLine(h);
            Console.WriteLine(new string('-', h.Length));
        }

        public static void StepRows(string label, string classifier, IReadOnlyList<ReplayResult> results)
        {
            foreach (var (output, m) in new[]
                     {
                         ("clf", GaitMetrics.Pool(results.Select(r => r.ClassifierMetrics))),
                         ("avatar", GaitMetrics.Pool(results.Select(r => r.AnimatorMetrics))),
                     })
            {
                if (m.Comparisons == 0) continue;
                Console.WriteLine(string.Format(CultureInfo.InvariantCulture, StepFormat, Trim(label, 20), classifier, output,
                    F(m.StepTimingMeanMs, "F0"), F(m.StepTimingSdMs, "F0"), P(m.StepRecall), P(m.StepPrecision), P(m.StepRightFoot),
                    P(m.WalkingAsStanding), P(m.StandingAsWalking), F(m.BoutsPerWalk, "F2"),
                    F(m.MeanStartDelaySeconds, "F2"), F(m.MeanStopDelaySeconds, "F2"), m.TrueSteps));
            }
        }

        static double MsPerWindow(IReadOnlyList<ReplayResult> results)
        {
            double windows = results.Sum(r => (double)r.Windows);
            return windows > 0 ? results.Sum(r => r.MeanWindowMs * r.Windows) / windows : double.NaN;
        }

        public static void Legend()
        {
            Console.WriteLine("miscl% = classifier output, avat% = what the avatar shows (animator), per foot and sample against the labels (standing is a class);");
            Console.WriteLine("adj%/avadj% = the same counting a phase one off as right; MAE/MSE/RMSE/CEP25-95 = classifier error in phase steps (cyclic 0-4, standing vs walking 4);");
            Console.WriteLine("delay_ms = predicted minus true phase onset (negative = early); ms/win = classifier CPU time per window on this machine; skip = unreadable rows + rejected samples.");
            Console.WriteLine("Steps: a contact is a foot entering stance from swing; IC_ms/IC_sd = predicted minus true contact time of matched steps (within 0.25 s);");
            Console.WriteLine("recall/prec% = true contacts found / predicted contacts that are real; foot% = matched steps on the right foot; walk>st = walking shown as standing, st>walk = standing shown as walking;");
            Console.WriteLine("bouts = walking bouts shown per true walking bout (1: each walk shows as one; more: walks broken apart or gestures shown as walking);");
            Console.WriteLine("start_s/stop_s = mean seconds from a labelled start (stop) of walking to the shown one, over walks that start (stop) inside a recording (- when none do).");
        }

        /// <summary>A label cut to n characters, keeping its end: recordings of one take differ in their last digits.</summary>
        static string Trim(string s, int n) => s.Length <= n ? s : s.Substring(0, n / 2 - 2) + ".." + s.Substring(s.Length - (n - n / 2));
    }
}
