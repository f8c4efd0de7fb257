using System.Collections.Generic;
using System.Globalization;
using System.IO;

namespace HeadGait
{
    /// <summary>
    /// One CSV row per scored recording, classifier and output (classifier or avatar): which recordings fail, and how.
    /// Written by <c>headgait benchmark --per-recording</c>; shares are fractions (0..1), counts are samples or steps, step
    /// timing the matched initial contacts' mean error in ms. The variant says what was scored: the clip as recorded,
    /// changed as the benchmark's variants change it (ear-like, slow, ...), or its head-pose recording through the pose path.
    /// </summary>
    public static class RecordingScoresCsv
    {
        public const string Header = "scheme,fold,variant,recording,classifier,output,samples,miscl,beyond_adjacent,walking_samples,walking_as_standing,standing_samples,standing_as_walking,true_steps,predicted_steps,matched_steps,step_timing_ms,right_foot,true_walking_bouts,shown_walking_bouts";

        /// <summary>What <see cref="Row.Variant"/> says of a clip scored as it was recorded.</summary>
        public const string AsRecorded = "recorded";

        /// <summary>A held-out recording's replay, the cross-validation fold that held it out and the variant scored (null: <see cref="AsRecorded"/>).</summary>
        public struct Row
        {
            public string Scheme, Fold, Variant;
            public ReplayResult Result;
        }

        public static void Write(TextWriter writer, IEnumerable<Row> rows)
        {
            writer.WriteLine(Header);
            foreach (var row in rows)
            {
                var r = row.Result;
                WriteLine(writer, row, "clf", r.ClassifierMetrics);
                WriteLine(writer, row, "avatar", r.AnimatorMetrics);
            }
        }

        static void WriteLine(TextWriter w, Row row, string output, GaitMetrics m)
        {
            if (m == null) return;
            var r = row.Result;
            w.WriteLine(string.Join(",", Field(row.Scheme), Field(row.Fold), Field(row.Variant ?? AsRecorded), Field(r.Recording), Field(r.Classifier), output,
                (m.Comparisons / 2).ToString(CultureInfo.InvariantCulture), Share(m.MisclassificationRate), Share(m.MisclassificationBeyondAdjacent),
                m.WalkingSamples.ToString(CultureInfo.InvariantCulture), Share(m.WalkingAsStanding),
                m.StandingSamples.ToString(CultureInfo.InvariantCulture), Share(m.StandingAsWalking),
                m.TrueSteps.ToString(CultureInfo.InvariantCulture), m.PredictedSteps.ToString(CultureInfo.InvariantCulture),
                m.MatchedSteps.ToString(CultureInfo.InvariantCulture), Milliseconds(m.StepTimingMeanMs), Share(m.StepRightFoot),
                m.TrueWalkingBouts.ToString(CultureInfo.InvariantCulture), m.ShownWalkingBouts.ToString(CultureInfo.InvariantCulture)));
        }

        // Empty where there is nothing to divide by (no standing in a walking clip), so no one averages a NaN.
        static string Share(double v) => double.IsNaN(v) ? "" : v.ToString("0.######", CultureInfo.InvariantCulture);

        // A recording's matched steps' mean timing (late positive): which walkers come out early or late.
        static string Milliseconds(double v) => double.IsNaN(v) ? "" : v.ToString("0.#", CultureInfo.InvariantCulture);

        // Recording names come from file names: quote any that would break the row.
        static string Field(string s)
        {
            s = s ?? "";
            return s.IndexOfAny(new[] { ',', '"', '\n', '\r' }) < 0 ? s : "\"" + s.Replace("\"", "\"\"") + "\"";
        }
    }
}
