using System;
using System.Collections.Generic;
using HeadGait.Synthetic;

namespace HeadGait
{
    /// <summary>
    /// The last check before a trained file is used: its classifier runs through the live pipeline on reference windows (a
    /// generated walker standing, then walking) and must decide more than one thing. A model whose values parse but cannot
    /// come from training (an SVM gamma of 1e300, a template cut short) decides standing, walking or one phase on every
    /// window; it is refused with <see cref="ModelFormatException"/>, and the caller falls back to the next simpler classifier
    /// with a warning (<see cref="GaitModels"/>, GaitClassifierBuilder).
    /// </summary>
    public static class DecisionCheck
    {
        /// <summary>Seconds of standing, then of walking, in the reference stream (about 550 windows).</summary>
        public const double StandingSeconds = 1.5, WalkingSeconds = 4;

        static List<RecordedSample> reference;

        /// <summary>The generated reference stream (made once; its first <see cref="StandingSeconds"/> stand).</summary>
        static List<RecordedSample> Reference
        {
            get
            {
                if (reference != null) return reference;
                var script = new StreamScript { StartTime = 0 }.Stand(StandingSeconds).Walk(WalkingSeconds, Foot.Left);
                return reference = WalkingStreamGenerator.Generate("reference", new GaitSubject(), script, 11).Samples;
            }
        }

        /// <summary>Throws when <paramref name="classifier"/> decides one class on every reference window; resets it after.</summary>
        public static void Require(IGaitClassifier classifier, string source)
        {
            if (classifier == null) throw new ArgumentNullException(nameof(classifier));
            var pipeline = new GaitPipeline(classifier);
            int standing = 0, standingShownStanding = 0, walking = 0, walkingShownWalking = 0;
            var phases = new HashSet<GaitPhase>();
            bool truthWalking = false;
            pipeline.FrameProduced += (p, f) =>
            {
                if (truthWalking)
                {
                    walking++;
                    if (p.IsWalking)
                    {
                        walkingShownWalking++;
                        phases.Add(p.Left);
                    }
                }
                else
                {
                    standing++;
                    if (!p.IsWalking) standingShownStanding++;
                }
            };
            foreach (var s in Reference)
            {
                truthWalking = s.HasTruth && s.Left != GaitPhase.Standing;
                pipeline.Push(s.Imu);
            }
            classifier.Reset();
            if (walking > 0 && walkingShownWalking == 0)
                throw new ModelFormatException(source, $"decides standing on all {walking} reference walking windows (a generated walker): values no training produces; refused");
            if (standing > 0 && standingShownStanding == 0)
                throw new ModelFormatException(source, $"decides walking on all {standing} reference standing windows (a generated walker): values no training produces; refused");
            if (walkingShownWalking > 0 && phases.Count < 2)
                throw new ModelFormatException(source, $"decides one phase on all {walkingShownWalking} reference windows it shows walking: values no training produces; refused");
        }
    }
}
