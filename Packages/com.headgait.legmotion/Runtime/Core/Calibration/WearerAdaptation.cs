using System;
using System.Collections.Generic;
using HeadGait.Training;

namespace HeadGait.Calibration
{
    /// <summary>Which parts of the classifiers a calibration walk refits (the defaults are the measured choice; see <see cref="WearerAdaptation"/>).</summary>
    public sealed class AdaptationSettings
    {
        /// <summary>Add the wearer's own mean step in front of COR's trained templates.</summary>
        public bool CorTemplate = true;
        /// <summary>Steps from which a walk adds the wearer's own step to COR (<see cref="CorTemplate"/>); fewer: COR as trained.</summary>
        public int CorTemplateSteps = WearerAdaptation.MinSteps;
        /// <summary>
        /// Self-supervised, the wearer's own step needs this many sure steps: a step averaged from six contacts COR itself
        /// found matched that style's bows and waves (bn1 *chimpira*: gestures shown as walking 8.0 to 9.6 %, misclassified
        /// 17.9 to 19.2 %), while nine gave the *childish* and *musical* styles 7-8 points (chosen on those held-out styles).
        /// </summary>
        public const int SelfSupervisedTemplateSteps = 8;
        /// <summary>Recalibrate COR's correlation threshold and contact lags on the walk whatever its length (else only from <see cref="CorThresholdSteps"/>).</summary>
        public bool CorThreshold;
        /// <summary>
        /// Steps from which a walk recalibrates COR's correlation threshold, contact lags and clock lead: a minute's walk
        /// holds about a hundred; on one clip of 8-13 steps they overfit (a style's other clips up to 32 points worse).
        /// </summary>
        public int CorThresholdSteps = 60;
        /// <summary>Recalibrate COR's clock lead on the walk whatever its length (else only from <see cref="CorThresholdSteps"/>, as the threshold).</summary>
        public bool CorLead;
        /// <summary>Recalibrate THR's floor, lag and sideways profile on the walk, then its clock lead.</summary>
        public bool Threshold = true;
        /// <summary>
        /// Open THR's and COR's walking gates as far as the wearer's walking needs (bounded): off. With ankle trackers it
        /// helped one style and cost another; self-supervised on real glasses it showed standing, head movement and picking up
        /// as walking more, and the wearer's own stillness, which could bound it, is not recorded at calibration.
        /// </summary>
        public bool DetectorGates;
        /// <summary>
        /// Open the learned models' gate as far as the wearer's walking needs (bounded; ankle trackers only, as their labels
        /// say where the wearer walked; kept only where it pays on the walk, with the input gain).
        /// </summary>
        public bool LearnedGate = true;
        /// <summary>
        /// With ankle trackers, open COR's walking gate for walks in progress (<see cref="CorGateWhileWalking"/>) as far as the
        /// walk's walking windows need (<see cref="WalkingGate.DetectorPass"/> of them passing, at most <see cref="MaxCorGateShift"/>),
        /// or by the smaller step of <see cref="WearerAdaptation.CorGateShiftStep"/> that scores the walk best, kept only where that
        /// beats the chosen COR on the walk by a COR candidate's margin (<see cref="ShortWalkMargin"/> on a
        /// walk of under <see cref="CorThresholdSteps"/> steps, else <see cref="CorAcceptMargin"/>): the ankles say where the
        /// wearer walked, so a gate that refuses their walking shows on the walk's score. Style CV, COR, in-sample as a
        /// choice: bn1 *feminine* (0.70 s a step, one clip of 12 steps, a quarter of its walking refused) 41.3 to 34.5 %
        /// (pooled 21.4 to 18.0 %; 36.9 % at a bound of 2), its gestures and bows never shown walking; no other style's opened gate paid on its walk
        /// (unjudged, as <see cref="DetectorGates"/>, bn1 *musical*'s gestures were shown walking 1.6 to 2.0 %).
        /// Self-supervised off: the labels come from COR itself, read with its gate open.
        /// </summary>
        public bool CorGate = true;
        /// <summary>
        /// With <see cref="CorGate"/>, open COR's gate only for a walk in progress (<see cref="CorrelationTemplate.WalkingGateHoldShift"/>):
        /// a start still needs the trained gate. Opened for starts too, bn1 *feminine* scored 35.7 instead of 36.9 %, but a
        /// generated calm wearer's standing with head movement was shown walking 0.9 % instead of never (0.75 % opened by 1).
        /// </summary>
        public bool CorGateWhileWalking = true;
        /// <summary>Most <see cref="CorGate"/> opens COR's gate (log-odds; at most <see cref="WearerProfile.MaxCorGateShift"/>).</summary>
        public double MaxCorGateShift = WearerProfile.MaxCorGateShift;
        /// <summary>Most a calibration opens a walking gate (log-odds; at most <see cref="WearerProfile.MaxGateShift"/>).</summary>
        public double MaxGateShift = WearerProfile.MaxGateShift;
        /// <summary>Most a calibration opens the learned models' walking gate (at most <see cref="WearerProfile.MaxLearnedGateShift"/>).</summary>
        public double MaxLearnedGateShift = WearerProfile.MaxLearnedGateShift;
        /// <summary>
        /// Keep each refitted part only where it scores the calibration walk itself better than the trained one by at least
        /// this much misclassification (0.01 = a point); NaN keeps every part.
        /// </summary>
        public double AcceptMargin = 0.005;
        /// <summary>
        /// The settings for a walk labelled from ankle trackers, or self-supervised: there THR is not refitted, as the labels
        /// come from COR's own contacts and a refitted THR followed them into worse contact timing (a minute's walk: pooled
        /// 23.5 to 23.9 %), the learned gate stays, as the sure stretches are where the wearer's steps were clearest, and the
        /// learned models' time scale stays 1 (<see cref="LearnedTimeScale"/>).
        /// </summary>
        public static AdaptationSettings For(string source) => source == WearerProfile.SelfSupervised
            ? new AdaptationSettings { Threshold = false, CorGate = false, LearnedGate = false, LearnedRefit = false, LearnedTimeScale = false, CorTemplateSteps = SelfSupervisedTemplateSteps, PreferFullerCorRefit = false, ShortWalkMargin = double.NaN, CorOwnTemplates = 1 }
            : new AdaptationSettings();

        /// <summary>Steps at which THR's refitted values and the trained ones weigh the same (shrinks a short walk's fit towards training).</summary>
        public double ThresholdPriorSteps = 20;
        /// <summary>Scale the learned models' input towards the training walkers' bounce.</summary>
        public bool LearnedGain = true;
        /// <summary>
        /// Read the learned models' input at a time scale (<see cref="WearerProfile.LearnedTimeScale"/>) set from the walk's
        /// step period: a quick wearer's window holds a shorter stretch of their walk, resampled, so that their steps take the
        /// training walkers' time (the window as it is still decides whether they walk). Style CV, SVM, ankle trackers:
        /// pooled 19.3 to 16.8 % (bn *active*, 0.44 s a step, read at 0.82: 27.5 to 18.0 %; bn1 *chimpira* at 0.86 the
        /// same as uncalibrated; the other seven styles slower, unscaled), gestures and bows shown as walking as without it.
        /// Self-supervised off: pooled 21.1 to 17.9 %, but on the glasses the one wearer it scaled (0.70) showed picking up
        /// as walking a little longer with the BLSTM. See <see cref="LearnedTimeScaleUpward"/> for slow wearers.
        /// </summary>
        public bool LearnedTimeScale = true;
        /// <summary>How much of the way from 1 to the wearer's period ratio the time scale goes (1: all of it).</summary>
        public double LearnedTimeScaleShare = 1;
        /// <summary>
        /// Also scale a wearer slower than the training walkers (a time scale above 1): off. Style CV, SVM, ankle trackers,
        /// scale from the calibration walk's period: every slow style scored worse than with its profile unscaled (bn1
        /// *feminine* at 1.26 29.7 to 32.7 %, *giant* 1.18 13.4 to 15.4, bn *masculine* 1.14 14.1 to 15.0, *feminine* 1.08
        /// 15.6 to 18.8, bn1 *childish* 1.08 33.5 to 35.9): training already stretches its walks up to 1.8 times slower
        /// (<see cref="HeadGait.Training.WearerSettings"/>), while the quick bn *active* (0.82) gained 27.5 to 18.0 %.
        /// </summary>
        public bool LearnedTimeScaleUpward;
        /// <summary>
        /// Refit the learned models' channel gains and output biases on the walk's labelled windows (<see cref="LearnedAdaptation"/>;
        /// ankle trackers only: self-supervised labels are COR's contacts, which the SVM would learn to follow).
        /// </summary>
        public bool LearnedRefit = true;
        /// <summary>
        /// With <see cref="LearnedRefit"/>, also search each input channel's gain: off, as a calm wearer's refitted channel
        /// gains showed the same wearer's standing with head movement as walking more (BLSTM, generated: 2.45 to 2.47 %);
        /// the output shifts cannot (they only pick the walking class), the gains move every decision.
        /// </summary>
        public bool LearnedChannelGains;
        /// <summary>
        /// With <see cref="LearnedRefit"/>, search the SVM's input channels' gains (the BLSTM's only with <see cref="LearnedChannelGains"/>).
        /// Style CV, SVM, ankle trackers (in-sample as a choice): pooled 21.0 to 16.8 % without, 16.4 % with; the slowest two
        /// styles bn1 *feminine* -4.59 to -4.83 and *giant* -1.07 to -2.04 points against uncalibrated, gestures and bows shown
        /// as walking never more (pooled 0.8 to 0.6 %), no style worse than uncalibrated (bn1 *active* gains 1.3 instead of 4.0).
        /// The generated calm wearer's head movement that kept <see cref="LearnedChannelGains"/> off was the BLSTM's.
        /// </summary>
        public bool SvmChannelGains = true;
        /// <summary>Most the refit moves one of the learned models' output biases (<see cref="LearnedAdaptation.DefaultShiftCap"/>; at most <see cref="LearnedAdjustment.MaxBiasShift"/>).</summary>
        public double LearnedShiftCap = LearnedAdaptation.DefaultShiftCap;
        /// <summary>L2 pull of the refit's output shifts towards none (<see cref="LearnedAdaptation.BiasPrior"/>).</summary>
        public double LearnedShiftPrior = LearnedAdaptation.BiasPrior;
        /// <summary>Move the refit's output shifts further where the walk replayed through the whole classifier pays (<see cref="LearnedAdaptation"/>'s search).</summary>
        public bool LearnedShiftSearch = true;
        /// <summary>Most the search moves an output shift (<see cref="LearnedAdaptation.DefaultSearchCap"/>; at most <see cref="LearnedAdjustment.MaxBiasShift"/>).</summary>
        public double LearnedSearchCap = LearnedAdaptation.DefaultSearchCap;
        /// <summary>
        /// Self-supervised: read COR's contacts with its walking gate open (<see cref="WearerAdaptation.SelfLabel"/>). The wearer
        /// was asked to walk, so the gate has nothing to decide, and a gate that refuses a calm walker's steps leaves nothing to
        /// fit on (nor anything to tell how far that wearer's gate must open); the steady rhythm alone picks the sure stretches.
        /// </summary>
        public bool LabelWithGateOpen = true;
        /// <summary>Self-supervised: a step COR missed in a steady rhythm (a gap of two steps) is filled in (<see cref="WearerAdaptation.SelfLabel"/>).</summary>
        public bool FillMissedSteps = true;
        /// <summary>
        /// With <see cref="FillMissedSteps"/>, missed steps are filled in only when COR's own contacts give fewer sure steps than
        /// this (0: always): a filled contact carries no side evidence and sits midway by the rhythm, which blurred the fit of
        /// a walker COR follows well. Held out (self-supervised, a minute's walk): bn *feminine* 19.7 to 16.6 %, *active* 23.4
        /// to 23.2 %, pooled 20.4 to 19.4 % (none 21.4 %), no style worse; the glasses' 20 wearers unchanged (one, d1-user5,
        /// gives 79 sure steps of its own instead of 92 filled and keeps the shipped COR; pooled figures the same); the 18 whose own contacts give fewer
        /// (at most 54), the calm wearers filling was made for, are filled in as before. 60: <see cref="CorThresholdSteps"/>, a minute's worth.
        /// </summary>
        public int FillMissedBelowSteps = 60;
        /// <summary>
        /// Of COR's candidates that beat the trained COR on the walk by the margin, keep the most refitted (else the one that
        /// scores the walk best). With ankle trackers: their labels place each phase's end a little off the motion capture's,
        /// so between two candidates that both pay, the walk's own score did not tell which scored the wearer's other walks
        /// better (held-out bn *feminine*: the wearer's step alone 26.6 % on the walk, 19.9 % on the other walks; refitted
        /// from 103 steps 27.2 and 15.9 %; scoring each kind fitted on one half of the walk on the other half chose the same
        /// as the walk's own score); it told well whether a candidate beats the trained one (bn *masculine*: neither, and
        /// both scored its other walks worse). Self-supervised: off.
        /// </summary>
        public bool PreferFullerCorRefit = true;
        /// <summary>
        /// On a walk of fewer than <see cref="CorThresholdSteps"/> steps, a COR candidate must beat the trained COR on the walk
        /// by this much (misclassification; NaN: <see cref="AcceptMargin"/> only): one clip of 8-13 steps scores it on few
        /// steps. Held-out (in-sample as a choice): bn1 *feminine*'s one clip 53.6 to 51.0 % with its own step, its other
        /// walks 41.3 to 41.9 %; *childish*, *giant* and *musical* gained 10-22 points on their clip and 7-10 on their other
        /// walks. Self-supervised: NaN.
        /// </summary>
        public double ShortWalkMargin = 0.05;
        /// <summary>
        /// On a walk of <see cref="CorThresholdSteps"/> or more, a COR candidate must beat the trained COR on the walk by this
        /// much (misclassification), at least <see cref="AcceptMargin"/>. With ankle trackers at half a point, bn *masculine*'s
        /// refitted candidate (its own step, lead 0.010 s) paid on its minute's walk by a hair once the fold COR's clock lead
        /// moved a little (COR's replaced contacts, 2026-11-26) and scored its other walks 15.7 to 18.6 %; at a point it is not
        /// kept, and every other style's gain stays (pooled 21.4 to 19.1 % at half a point, 18.3 % at a point). The learned
        /// models keep half a point: at a point the SVM's bn1 *active* lost its gain (24.4 to 28.6 %).
        /// </summary>
        public double CorAcceptMargin = 0.01;
        /// <summary>
        /// Mean steps the wearer's own steps make on a walk of <see cref="CorThresholdSteps"/> or more (clustered as training
        /// clusters; a shorter walk makes one), added in front of the trained ones. With ankle trackers, held-out (in-sample
        /// as a choice among 1-3, added or in place of the trained ones): a minute's straight walks and turns gave bn
        /// *feminine* 15.9 to 15.2 % with two; three, or the wearer's steps alone in the refitted candidate, showed bn
        /// *masculine* worse than uncalibrated (up to +2.3 points). Self-supervised: 1 (two cost bn *feminine* 19.7 to 25.0 %).
        /// </summary>
        public int CorOwnTemplates = 2;
        /// <summary>
        /// Self-supervised: a COR candidate, and the learned models' input gain, is kept only where, replayed over the whole
        /// calibration walk, it shows no more time as walking outside the walk's own step rhythm (<see cref="RhythmReference"/>)
        /// than the trained classifier (<see cref="WearerAdaptation.OutsideRhythmWalking"/>): the sure stretches it is scored on hold
        /// only walking, so nothing else tells a wearer's own step, or a calm wearer's larger gain, that also shows their
        /// pauses and turns on the spot as walking.
        /// </summary>
        public bool StillCheck = true;
        /// <summary>With <see cref="StillCheck"/>, seconds of walking outside the rhythm a candidate may add over the trained classifier.</summary>
        public double StillSlack;
    }

    /// <summary>
    /// Fits the classifiers to one wearer from a calibration walk, in C# and in seconds: COR's step templates (the wearer's
    /// own mean step added in front of the trained ones; from <see cref="AdaptationSettings.CorThresholdSteps"/> steps also
    /// the correlation threshold, contact lags and clock lead recalibrated on the walk, whichever scores it best), THR's
    /// floor, lag, sideways profile and clock lead (recalibrated starting from the trained settings), how far the learned
    /// models' walking gate must open to pass the wearer's walking, and their input gain. The walk is labelled either from
    /// two ankle trackers (<see cref="FootContactLabeller"/>) or by the shipped COR itself (<see cref="SelfLabel"/>).
    /// Bounded so that it cannot make standing walk: a detector's gate opens by at most <see cref="WearerProfile.MaxGateShift"/>
    /// (COR's, with ankle trackers and only where that pays on the walk, by <see cref="WearerProfile.MaxCorGateShift"/>), the learned models' by <see cref="WearerProfile.MaxLearnedGateShift"/>, COR's
    /// threshold drops by at most <see cref="MaxThresholdDrop"/> (none), THR's floor to no less than
    /// <see cref="MinFloorShare"/> of the trained one.
    /// </summary>
    public static class WearerAdaptation
    {
        /// <summary>Steps a calibration walk must hold.</summary>
        public const int MinSteps = 6;

        /// <summary>
        /// Largest drop of COR's correlation threshold below the trained one: none. A minute's walk that pulled it down
        /// (*active*, 0.70 to 0.65) showed the style's gestures as walking more (2.1 to 3.1 %) and misclassified more; the
        /// walks that raised it gained (*feminine*, 0.78 to 0.79: 22.9 to 17.9 %).
        /// </summary>
        public const double MaxThresholdDrop = 0;

        /// <summary>THR's floor stays at least this share of the trained floor.</summary>
        public const double MinFloorShare = 0.6;

        /// <summary>Augmented copies of the walk the fit also reads (as training does: the wearer's steps vary too).</summary>
        public const int AugmentedCopies = 2;

        /// <summary>
        /// A profile from a labelled calibration walk (labels from ankle trackers, or <see cref="SelfLabel"/>'s). Throws
        /// <see cref="InvalidOperationException"/> when the walk holds fewer than <see cref="MinSteps"/> steps or the models
        /// lack THR or COR.
        /// </summary>
        public static WearerProfile Fit(GaitModels models, IReadOnlyList<Recording> walk, string wearer, string source = WearerProfile.FromFootReferences, AdaptationSettings settings = null, Recording unlabelled = null)
        {
            var a = settings ?? AdaptationSettings.For(source);
            if (models?.Correlation == null || models.Threshold == null) throw new InvalidOperationException("Calibration needs the trained THR settings and COR template.");
            int steps = 0;
            foreach (var r in walk) steps += PhaseEvents.TruthSteps(r).Count;
            if (steps < MinSteps) throw new InvalidOperationException($"The calibration walk holds {steps} steps (at least {MinSteps} are needed): walk for longer.");
            var training = GaitTraining.WithAugmentation(walk, AugmentedCopies);
            var baseCor = models.Correlation;
            var baseThr = models.Threshold;

            bool ownStep = a.CorTemplate && steps >= a.CorTemplateSteps;
            var corGate = a.DetectorGates ? WearerProfile.OpenGate(baseCor.Gate, GateShift(baseCor.Gate, walk, WalkingGate.DetectorPass, Math.Min(a.MaxGateShift, WearerProfile.MaxGateShift))) : baseCor.Gate;
            bool refitThreshold = a.CorThreshold || steps >= a.CorThresholdSteps, refitLead = a.CorLead || steps >= a.CorThresholdSteps;
            var corCandidates = CorCandidates(baseCor, corGate, training, ownStep, refitThreshold, refitLead, steps >= a.CorThresholdSteps ? Math.Max(1, a.CorOwnTemplates) : 1);
            var thrGate = a.DetectorGates ? WearerProfile.OpenGate(baseThr.Gate, GateShift(baseThr.Gate, walk, WalkingGate.DetectorPass, Math.Min(a.MaxGateShift, WearerProfile.MaxGateShift))) : baseThr.Gate;
            var thr = baseThr.Clone();
            thr.Gate = thrGate;
            if (a.Threshold)
            {
                var refit = ThresholdClassifier.Calibrate(training, baseThr.PhaseMap, thrGate, baseThr);
                refit.Floor = Math.Max(refit.Floor, MinFloorShare * baseThr.Floor);
                var refitFitted = refit.Clone();
                refit.Clock.Lead = GaitTraining.ContactTiming(() => new ThresholdClassifier(refitFitted), training);
                thr = Shrunk(baseThr, refit, steps / (steps + a.ThresholdPriorSteps));
            }

            // Each part only where it pays on the walk itself.
            var shippedCor = baseCor.With(gate: corGate);
            var shippedThr = baseThr.Clone();
            shippedThr.Gate = thrGate;
            var still = unlabelled == null ? null : new StillCheck(unlabelled, a.StillSlack);
            var (cor, corScore) = ChooseCor(shippedCor, corCandidates, walk, a, steps, still);
            if (a.CorGate) cor = OpenedCorGate(cor, corScore, baseCor.Gate, walk, a, steps);
            if (!Pays(() => new ThresholdClassifier(thr), () => new ThresholdClassifier(shippedThr), walk, a.AcceptMargin)) thr = shippedThr;

            var learnedGate = LearnedGate(models);
            var profile = new WearerProfile
            {
                Wearer = wearer,
                Source = source,
                Steps = steps,
                BaseModels = WearerProfile.Fingerprint(models),
                Threshold = thr,
                Correlation = cor,
                LearnedGateShift = learnedGate == null || !a.LearnedGate ? 0 : GateShift(learnedGate, walk, WalkingGate.LearnedPass, Math.Min(a.MaxLearnedGateShift, WearerProfile.MaxLearnedGateShift)),
                LearnedGain = a.LearnedGain ? LearnedGain(baseCor.LeadReferenceBounce, walk) : 1,
            };
            // The learned models' scaling too only where it pays on the walk (the SVM's and the BLSTM's scores together).
            if (profile.LearnedGain != 1 || profile.LearnedGateShift != 0)
            {
                var learned = models.Svm ?? models.Blstm;
                bool isSvm = models.Svm != null;
                if (learned == null) profile.LearnedGain = 1;
                else
                {
                    LearnedClassifier Make(ModelFile f) => isSvm ? models.SvmOf(f) : models.BlstmOf(f);
                    var scaled = profile.ScaledModel(learned);
                    if (!Pays(() => Make(scaled), () => Make(learned), walk, a.AcceptMargin) || !LearnedScalingStill(profile, models, still))
                    {
                        profile.LearnedGain = 1;
                        profile.LearnedGateShift = 0;
                    }
                }
            }
            if (a.LearnedTimeScale) profile.LearnedTimeScale = TimeScale(models, walk, a, profile, still);
            if (a.LearnedRefit)
            {
                Refit(profile, models.Svm, models.SvmOf, walk, a, a.LearnedChannelGains || a.SvmChannelGains);
                Refit(profile, models.Blstm, models.BlstmOf, walk, a, a.LearnedChannelGains);
            }
            return profile;
        }

        /// <summary>
        /// The learned models' time scale (<see cref="WearerProfile.LearnedTimeScale"/>) from the walk's median step
        /// (<see cref="StepPeriod"/>) over the training walkers' (half the model's <see cref="PhaseMap.ReferenceStridePeriod"/>),
        /// moved <see cref="AdaptationSettings.LearnedTimeScaleShare"/> of the way from 1 and within the profile's bounds;
        /// only below 1 (a wearer quicker than the training walkers) unless <see cref="AdaptationSettings.LearnedTimeScaleUpward"/>.
        /// Set from the period, not judged on the walk: scored on the walk, with or without the output shifts refitted at
        /// it, the scale that paid held out (bn *active*) was refused and ones that cost were kept (see the settings).
        /// Self-supervised, kept only where it passes the still check. 1 otherwise.
        /// </summary>
        static double TimeScale(GaitModels models, IReadOnlyList<Recording> walk, AdaptationSettings a, WearerProfile profile, StillCheck still)
        {
            var learned = models.Svm ?? models.Blstm;
            if (learned == null) return 1;
            double wearerStep = StepPeriod(walk);
            double trainedStep = (models.Svm != null ? models.SvmOf(learned) : models.BlstmOf(learned)).TrainedStepPeriod;
            if (!(wearerStep > 0)) return 1;
            double scale = Math.Round(Math.Max(WearerProfile.MinLearnedTimeScale, Math.Min(WearerProfile.MaxLearnedTimeScale, 1 + a.LearnedTimeScaleShare * (wearerStep / trainedStep - 1))), 3);
            if (Math.Abs(scale - 1) < MinTimeScaleChange || scale > 1 && !a.LearnedTimeScaleUpward) return 1;
            if (still == null) return scale;
            double kept = profile.LearnedTimeScale;
            profile.LearnedTimeScale = scale;
            bool passes = LearnedScalingStill(profile, models, still);
            profile.LearnedTimeScale = kept;
            return passes ? scale : 1;
        }

        /// <summary>Least change of the learned models' time scale a profile takes (a wearer within a step or two a minute of the training walkers reads as they do).</summary>
        public const double MinTimeScaleChange = 0.02;

        /// <summary>The walk's median step (s; truth steps of 0.25 to 2 s), or NaN without <see cref="MinSteps"/> of them.</summary>
        public static double StepPeriod(IReadOnlyList<Recording> walk)
        {
            var steps = new List<double>();
            foreach (var r in walk)
                foreach (var step in PhaseEvents.TruthSteps(r, 0.25, 2.0)) steps.Add(step.Duration);
            return steps.Count < MinSteps ? double.NaN : GaitMetrics.Median(steps);
        }

        /// <summary>
        /// COR's candidates from a walk, from the least refitted: the wearer's own mean steps (<paramref name="ownCount"/>)
        /// added in front of the trained ones (their lag the trained templates' median), then with the threshold (never below
        /// the trained one), lags and clock lead recalibrated on the walk (where <paramref name="refitThreshold"/> or
        /// <paramref name="refitLead"/>).
        /// </summary>
        static List<CorrelationTemplate> CorCandidates(CorrelationTemplate baseCor, WalkingGate corGate, IReadOnlyList<Recording> training, bool ownStep, bool refitThreshold, bool refitLead, int ownCount)
        {
            var ownTemplates = ownStep ? CorrelationTemplate.Train(training, baseCor.PhaseMap, corGate, ownCount).Templates : new List<StepTemplate>();
            var templates = new List<StepTemplate>(ownTemplates);
            foreach (var t in baseCor.Templates)
                if (templates.Count < 16) templates.Add(t);
            var cor = baseCor.With(templates: templates, gate: corGate);
            var candidates = new List<CorrelationTemplate>();
            if (ownStep)
            {
                var lags = new List<double>();
                foreach (var t in baseCor.Templates) lags.Add(t.ContactLag);
                var own = new List<StepTemplate>(templates);
                for (int k = 0; k < ownTemplates.Count; k++) own[k] = own[k].WithLag(GaitMetrics.Median(lags));
                candidates.Add(cor.With(templates: own));
            }
            if (refitThreshold || refitLead)
            {
                var refit = ownStep ? cor : baseCor.With(gate: corGate);
                if (refitThreshold)
                {
                    refit = CorrelationClassifier.Calibrate(refit, training);
                    refit = refit.With(minCorrelation: Math.Max(refit.MinCorrelation, baseCor.MinCorrelation - MaxThresholdDrop));
                }
                else if (ownStep) refit = candidates[0];
                if (refitLead)
                {
                    var fitted = refit;
                    refit = refit.With(clockLead: GaitTraining.ContactTiming(() => new CorrelationClassifier(fitted), training));
                }
                candidates.Add(refit);
            }
            return candidates;
        }

        /// <summary>
        /// Which of COR's candidates the profile keeps: the trained <paramref name="shipped"/> unless a candidate beats it on
        /// the walk by the settings' margin (<see cref="AdaptationSettings.ShortWalkMargin"/> on a short walk); of those that
        /// do, the most refitted (<see cref="AdaptationSettings.PreferFullerCorRefit"/>) or the best scoring. NaN margin: the
        /// most refitted, paying or not. With it, its misclassification of the walk where that was scored (else NaN).
        /// </summary>
        static (CorrelationTemplate Cor, double Score) ChooseCor(CorrelationTemplate shipped, List<CorrelationTemplate> candidates, IReadOnlyList<Recording> walk, AdaptationSettings a, int steps, StillCheck still)
        {
            if (still != null && candidates.Count > 0)
            {
                double trainedOutside = still.Outside(new CorrelationClassifier(shipped));
                candidates = candidates.FindAll(c => still.Keeps(new CorrelationClassifier(c), trainedOutside));
            }
            if (candidates.Count == 0) return (shipped, double.NaN);
            if (double.IsNaN(a.AcceptMargin)) return (candidates[candidates.Count - 1], double.NaN);
            double margin = CorMargin(a, steps);
            double trained = Misclassification(() => new CorrelationClassifier(shipped), walk);
            var chosen = shipped;
            double best = trained - margin, chosenScore = trained;
            foreach (var c in candidates)
            {
                var candidate = c;
                double score = Misclassification(() => new CorrelationClassifier(candidate), walk);
                bool pays = score <= trained - margin;
                if (a.PreferFullerCorRefit ? !pays : score > best) continue;
                best = chosenScore = score;
                chosen = candidate;
            }
            return (chosen, chosenScore);
        }

        /// <summary>The margin a COR candidate must beat the trained one by on a walk of <paramref name="steps"/> steps.</summary>
        static double CorMargin(AdaptationSettings a, int steps)
            => Math.Max(a.AcceptMargin, steps < a.CorThresholdSteps && !double.IsNaN(a.ShortWalkMargin) ? a.ShortWalkMargin : a.CorAcceptMargin);

        /// <summary>
        /// <paramref name="cor"/> (misclassifying the walk <paramref name="corScore"/>; NaN: not scored yet) with its walking gate
        /// opened (<see cref="AdaptationSettings.CorGate"/>) by the one of <see cref="CorGateShiftStep"/>, twice that, ... up to as far
        /// as the walk's walking windows need (with what <see cref="AdaptationSettings.DetectorGates"/> opened already, at most
        /// <see cref="AdaptationSettings.MaxCorGateShift"/> above <paramref name="trainedGate"/>) that scores the walk best, where
        /// that beats <paramref name="cor"/> on the walk by the walk's margin; else <paramref name="cor"/>.
        /// </summary>
        static CorrelationTemplate OpenedCorGate(CorrelationTemplate cor, double corScore, WalkingGate trainedGate, IReadOnlyList<Recording> walk, AdaptationSettings a, int steps)
        {
            double opened0 = cor.Gate.Weights[WalkingGate.InputCount] - trainedGate.Weights[WalkingGate.InputCount];
            double need = GateShift(cor.Gate, walk, WalkingGate.DetectorPass, Math.Min(a.MaxCorGateShift, WearerProfile.MaxCorGateShift) - opened0);
            if (!(need > 0)) return cor;
            CorrelationTemplate Opened(double shift) => a.CorGateWhileWalking ? cor.With(walkingGateHoldShift: shift) : cor.With(gate: WearerProfile.OpenGate(cor.Gate, shift));
            var best = cor;
            double bestScore = double.PositiveInfinity;
            for (int k = 1; ; k++)
            {
                double shift = Math.Min(need, k * CorGateShiftStep);
                var opened = Opened(shift);
                double score = Misclassification(() => new CorrelationClassifier(opened), walk);
                // The smaller opening on a tie.
                if (score < bestScore)
                {
                    bestScore = score;
                    best = opened;
                }
                if (shift >= need) break;
            }
            if (double.IsNaN(corScore)) corScore = Misclassification(() => new CorrelationClassifier(cor), walk);
            return bestScore <= corScore - CorMargin(a, steps) ? best : cor;
        }

        /// <summary>
        /// Steps (log-odds) of the openings <see cref="OpenedCorGate"/> tries. Only the full opening the walk needed, it was
        /// refused where the full opening overshot: a generated calm wearer's walk needed more than the bound, 2 scored it
        /// 3.4 points better, 1.5 7.4 points (CalibrationTests).
        /// </summary>
        public const double CorGateShiftStep = 0.5;

        /// <summary>
        /// Whether the profile's learned input gain and gate (<see cref="WearerProfile.ScaledModel"/>) pass the still check
        /// for each learned model shipped (the SVM and the BLSTM read the same gain): true without a check.
        /// </summary>
        static bool LearnedScalingStill(WearerProfile profile, GaitModels models, StillCheck still)
        {
            if (still == null) return true;
            if (models.Svm != null && !still.Keeps(models.SvmOf, models.Svm, profile.ScaledModel(models.Svm))) return false;
            if (models.Blstm != null && !still.Keeps(models.BlstmOf, models.Blstm, profile.ScaledModel(models.Blstm))) return false;
            return true;
        }

        /// <summary>
        /// The self-supervised still check (<see cref="AdaptationSettings.StillCheck"/>), one rule for every classifier: a
        /// refitted classifier is kept only where it shows at most <see cref="AdaptationSettings.StillSlack"/> seconds more
        /// walking outside the calibration walk's own rhythm (<see cref="OutsideRhythmWalking"/>) than the trained one.
        /// </summary>
        sealed class StillCheck
        {
            readonly Recording walk;
            readonly RhythmReference reference;
            readonly double slack;

            public StillCheck(Recording unlabelled, double slack)
            {
                walk = unlabelled;
                reference = RhythmReference.Of(unlabelled);
                this.slack = slack;
            }

            /// <summary>The classifier's walking outside the walk's rhythm (s).</summary>
            public double Outside(IGaitClassifier classifier) => OutsideRhythmWalking(classifier, walk, reference);

            /// <summary>Whether <paramref name="candidate"/> passes against the trained classifier's <see cref="Outside"/>.</summary>
            public bool Keeps(IGaitClassifier candidate, double trainedOutside) => Outside(candidate) <= trainedOutside + slack;

            /// <summary>Whether the learned model <paramref name="adapted"/> passes against <paramref name="trained"/>, both built by <paramref name="make"/>.</summary>
            public bool Keeps(Func<ModelFile, LearnedClassifier> make, ModelFile trained, ModelFile adapted) => Keeps(make(adapted), Outside(make(trained)));
        }

        /// <summary>Time around each walking bout of the rhythm that <see cref="OutsideRhythmWalking"/> leaves out (s): a first or last step the rhythm does not count.</summary>
        public const double BoutEdge = 1.0;

        /// <summary>
        /// Seconds of <paramref name="recording"/> the classifier predicts as walking farther than <see cref="BoutEdge"/> from
        /// every walking bout of its step rhythm (<paramref name="reference"/>): on a calibration walk, its pauses, turns on
        /// the spot and stop.
        /// </summary>
        public static double OutsideRhythmWalking(IGaitClassifier classifier, Recording recording, RhythmReference reference)
        {
            var predictions = ReplayEvaluator.Run(recording, classifier, keepTrace: true).Predictions;
            double seconds = 0;
            for (int i = 0; i + 1 < predictions.Count; i++)
            {
                if (!predictions[i].IsWalking) continue;
                double t = predictions[i].Time;
                if (!reference.IsNear(t, BoutEdge)) seconds += Math.Min(0.1, Math.Max(0, predictions[i + 1].Time - t));
            }
            return seconds;
        }

        /// <summary>
        /// Adds the learned model's refitted channel gains and output biases to the profile (<see cref="LearnedAdaptation"/>),
        /// where they score the walk replayed through the whole classifier (time filter, gate) better than the profile's
        /// scaling alone by the settings' <see cref="AdaptationSettings.AcceptMargin"/>.
        /// </summary>
        static void Refit(WearerProfile profile, ModelFile shipped, Func<ModelFile, LearnedClassifier> make, IReadOnlyList<Recording> walk, AdaptationSettings a, bool channelGains)
        {
            if (shipped == null) return;
            var scaled = profile.ScaledModel(shipped);
            var adjustment = LearnedAdaptation.Fit(shipped, scaled, make, walk, channelGains, a.LearnedShiftCap, a.LearnedShiftPrior, a.LearnedShiftSearch, a.LearnedSearchCap);
            if (adjustment == null || !adjustment.Changes) return;
            string biasName = make(scaled).OutputBiasName;
            var adjusted = adjustment.AppliedTo(scaled, biasName);
            if (Pays(() => make(adjusted), () => make(scaled), walk, a.AcceptMargin)) profile.LearnedAdjustments.Add(adjustment);
        }

        /// <summary>Whether <paramref name="adapted"/> misclassifies the walk less than <paramref name="shipped"/> by at least <paramref name="margin"/> (NaN: always).</summary>
        static bool Pays(Func<IGaitClassifier> adapted, Func<IGaitClassifier> shipped, IReadOnlyList<Recording> walk, double margin)
            => double.IsNaN(margin) || Misclassification(adapted, walk) <= Misclassification(shipped, walk) - margin;

        /// <summary>Pooled misclassification of the walk by fresh classifiers from <paramref name="make"/>.</summary>
        internal static double Misclassification(Func<IGaitClassifier> make, IReadOnlyList<Recording> walk)
        {
            var parts = new List<GaitMetrics>();
            foreach (var r in walk) parts.Add(ReplayEvaluator.Run(r, make()).ClassifierMetrics);
            return GaitMetrics.Pool(parts).MisclassificationRate;
        }

        /// <summary>THR's refitted floor, lag, sideways profile and clock lead moved from the trained ones by <paramref name="weight"/> of the way.</summary>
        static ThresholdSettings Shrunk(ThresholdSettings trained, ThresholdSettings refit, double weight)
        {
            double Mix(double a, double b) => a + weight * (b - a);
            var s = refit.Clone();
            s.Floor = Mix(trained.Floor, refit.Floor);
            s.ContactLag = Mix(trained.ContactLag, refit.ContactLag);
            if (!double.IsNaN(trained.DatingLevel) && !double.IsNaN(refit.DatingLevel)) s.DatingLevel = Mix(trained.DatingLevel, refit.DatingLevel);
            if (trained.LateralProfile.Length == refit.LateralProfile.Length)
            {
                s.LateralProfile = new double[refit.LateralProfile.Length];
                for (int i = 0; i < s.LateralProfile.Length; i++) s.LateralProfile[i] = Mix(trained.LateralProfile[i], refit.LateralProfile[i]);
            }
            s.Clock.Lead = Mix(trained.Clock.Lead, refit.Clock.Lead);
            s.Clock.LeadPerLogBounce = Mix(trained.Clock.LeadPerLogBounce, refit.Clock.LeadPerLogBounce);
            return s;
        }

        /// <summary>The walking gate written into the learned models (the SVM's, else the BLSTM's); null without one.</summary>
        static WalkingGate LearnedGate(GaitModels models)
        {
            foreach (var m in new[] { models.Svm, models.Blstm })
                if (m != null && m.Values.TryGetValue(WalkingGate.ModelKey, out var text)) return WalkingGate.Parse(text);
            return null;
        }

        /// <summary>
        /// Log-odds to add to <paramref name="gate"/> so that <paramref name="pass"/> of the walk's walking windows pass, as
        /// training set it for the training walkers (0 when they already do; at most <paramref name="most"/>).
        /// </summary>
        public static double GateShift(WalkingGate gate, IReadOnlyList<Recording> walk, double pass, double most = WearerProfile.MaxGateShift)
        {
            if (gate == null) return 0;
            var scores = new List<double>();
            foreach (var rec in walk)
            {
                var labels = new LabelCursor(rec);
                var pre = new StreamPreprocessor(new PreprocessorSettings { History = gate.History });
                foreach (var s in rec.Samples)
                    pre.Push(s.Imu, w =>
                    {
                        if (labels.TryLabelsAt(w.EndTime, out var truth) && truth.Left != GaitPhase.Standing) scores.Add(gate.Score(w));
                    });
            }
            if (scores.Count < 50) return 0;
            scores.Sort();
            double q = scores[(int)Math.Floor((1 - pass) * (scores.Count - 1))];
            return Math.Max(0, Math.Min(most, -q));
        }

        /// <summary>
        /// The learned models' input gain: the training walkers' typical step peak (SMV minus gravity, COR's
        /// <see cref="CorrelationTemplate.LeadReferenceBounce"/>) over the wearer's median step peak, within
        /// <see cref="WearerProfile.MinLearnedGain"/>..<see cref="WearerProfile.MaxLearnedGain"/>.
        /// </summary>
        public static double LearnedGain(double referenceBounce, IReadOnlyList<Recording> walk)
        {
            var peaks = new List<double>();
            foreach (var rec in walk)
            {
                var raw = new RawSignal(rec);
                foreach (var step in PhaseEvents.TruthSteps(rec))
                {
                    double peak = double.NegativeInfinity;
                    for (double t = step.Start; t <= step.End; t += 0.01) peak = Math.Max(peak, raw.Smv(t));
                    peaks.Add(peak);
                }
            }
            if (peaks.Count < MinSteps || !(referenceBounce > 0)) return 1;
            double median = GaitMetrics.Median(peaks);
            if (!(median > 0)) return 1;
            return Math.Max(WearerProfile.MinLearnedGain, Math.Min(WearerProfile.MaxLearnedGain, referenceBounce / median));
        }

        /// <summary>Contacts in a row (at least) that make a stretch of the walk the shipped COR is sure of.</summary>
        public const int MinSureContacts = 5;

        /// <summary>How far a step may differ from its stretch's median step (share) and still count as the same rhythm.</summary>
        public const double RhythmTolerance = 0.25;

        /// <summary>
        /// How COR reads a self-supervised walk's contacts: without a stronger match taking an earlier contact's place
        /// (<see cref="CorrelationSettings.ReplaceMargin"/>). With it, style CV self-supervised (`calibrate benchmark`,
        /// in-sample as a choice): bn *feminine*'s minute gave 68 sure steps of COR's own instead of 62 filled in, and its
        /// other walks scored 17.7 % (19.7 % with the replaced contacts dropped from the list) against 17.9 % without;
        /// pooled 19.9 / 20.5 against 19.7 % (uncalibrated 21.4 %).
        /// </summary>
        public static CorrelationSettings SelfLabelSettings => new CorrelationSettings { ReplaceMargin = -1 };

        /// <summary>
        /// Self-supervised labels (no foot references): the walk replayed through the shipped COR (its walking gate open
        /// where <paramref name="gateOpen"/>; a step it missed in a steady rhythm filled in where <paramref name="fillMissed"/>,
        /// see <see cref="WithMissedSteps"/>, and, when <paramref name="fillBelowSteps"/> is more than 0, only where COR's own
        /// contacts give fewer sure steps than that); every stretch of at least
        /// <see cref="MinSureContacts"/> contacts in a clear rhythm (each step within <see cref="RhythmTolerance"/> of the
        /// stretch's median, 0.3 to 1 s) becomes a labelled walking recording, its feet alternating from the side COR
        /// named most often and each foot's phases spread over its stride by the trained phase map. Empty when none is sure.
        /// </summary>
        public static List<Recording> SelfLabel(GaitModels models, Recording walk, bool gateOpen = true, bool fillMissed = true, int fillBelowSteps = 0)
        {
            if (models?.Correlation == null) throw new InvalidOperationException("Self-supervised calibration needs the trained COR template.");
            var cor = new CorrelationClassifier(gateOpen ? models.Correlation.With(gate: WalkingGate.Open) : models.Correlation, SelfLabelSettings);
            var contacts = new List<(double time, double evidence)>();
            cor.ContactDetected += (t, e, r, k) => contacts.Add((t, e));
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = cor.WindowLength });
            foreach (var s in walk.Samples) pre.Push(s.Imu, w => cor.Classify(w));
            if (fillMissed && fillBelowSteps > 0)
            {
                // Filled in only where COR's own contacts give too few sure steps (AdaptationSettings.FillMissedBelowSteps).
                var unfilled = SureStretches(walk, models.Correlation.PhaseMap, contacts);
                int steps = 0;
                foreach (var r in unfilled) steps += PhaseEvents.TruthSteps(r).Count;
                if (steps >= fillBelowSteps) return unfilled;
            }
            return SureStretches(walk, models.Correlation.PhaseMap, fillMissed ? WithMissedSteps(contacts) : contacts);
        }

        /// <summary>The stretches of steady contacts as labelled walking recordings (<see cref="SelfLabel"/>).</summary>
        static List<Recording> SureStretches(Recording walk, PhaseMap map, List<(double time, double evidence)> contacts)
        {
            var stretches = new List<Recording>();
            int start = 0;
            for (int i = 1; i <= contacts.Count; i++)
            {
                bool breaks = i == contacts.Count || !(contacts[i].time - contacts[i - 1].time >= 0.3 && contacts[i].time - contacts[i - 1].time <= 1.0);
                if (!breaks) continue;
                // Within the run [start, i), keep the longest part whose steps stay near its median step.
                AddSure(walk, map, contacts, start, i, stretches);
                start = i;
            }
            return stretches;
        }

        /// <summary>
        /// The contacts with one contact put midway into every gap of two of the walk's steps (its median step, within
        /// <see cref="RhythmTolerance"/>): a calm wearer's steps that COR missed, so that the stretch goes on through them
        /// (and the wearer's own template learns them). The filled contact carries no side evidence.
        /// </summary>
        static List<(double time, double evidence)> WithMissedSteps(List<(double time, double evidence)> contacts)
        {
            var steps = new List<double>();
            for (int i = 1; i < contacts.Count; i++)
            {
                double gap = contacts[i].time - contacts[i - 1].time;
                if (gap >= 0.3 && gap <= 1.0) steps.Add(gap);
            }
            if (steps.Count < MinSureContacts) return contacts;
            double step = GaitMetrics.Median(steps);
            var filled = new List<(double time, double evidence)>(contacts.Count);
            for (int i = 0; i < contacts.Count; i++)
            {
                if (i > 0)
                {
                    double gap = contacts[i].time - contacts[i - 1].time;
                    if (Math.Abs(gap - 2 * step) <= 2 * RhythmTolerance * step && gap / 2 <= 1.0) filled.Add((contacts[i - 1].time + gap / 2, 0));
                }
                filled.Add(contacts[i]);
            }
            return filled;
        }

        static void AddSure(Recording walk, PhaseMap map, List<(double time, double evidence)> contacts, int from, int to, List<Recording> stretches)
        {
            if (to - from < MinSureContacts) return;
            var steps = new List<double>();
            for (int i = from + 1; i < to; i++) steps.Add(contacts[i].time - contacts[i - 1].time);
            double median = GaitMetrics.Median(steps);
            int runStart = from;
            for (int i = from + 1; i <= to; i++)
            {
                bool steady = i < to && Math.Abs(contacts[i].time - contacts[i - 1].time - median) <= RhythmTolerance * median;
                if (steady) continue;
                if (i - runStart >= MinSureContacts) stretches.Add(Labelled(walk, map, contacts.GetRange(runStart, i - runStart), stretches.Count));
                runStart = i;
            }
        }

        /// <summary>The walk between the first and last of <paramref name="contacts"/>, labelled from them.</summary>
        static Recording Labelled(Recording walk, PhaseMap map, List<(double time, double evidence)> contacts, int index)
        {
            // Which foot the even contacts are: the side evidence of the even ones against the odd ones.
            double even = 0;
            for (int k = 0; k < contacts.Count; k++) even += (k % 2 == 0 ? 1 : -1) * contacts[k].evidence;
            bool evenLeft = even >= 0;
            double first = contacts[0].time, last = contacts[contacts.Count - 1].time;
            var samples = new List<RecordedSample>();
            foreach (var s in walk.Samples)
            {
                double t = s.Imu.Time;
                if (t < first || t > last) continue;
                samples.Add(new RecordedSample(s.Imu, FootPhase(map, contacts, t, evenLeft ? 0 : 1), FootPhase(map, contacts, t, evenLeft ? 1 : 0), s.Line));
            }
            return new Recording($"{walk.Name}_sure{index + 1}", samples);
        }

        /// <summary>The phase of the foot whose contacts are those of parity <paramref name="parity"/> at time t.</summary>
        static GaitPhase FootPhase(PhaseMap map, List<(double time, double evidence)> contacts, double t, int parity)
        {
            int n = contacts.Count;
            // The foot's last contact at or before t, and its next; beyond the ends a stride is the median of two steps.
            int before = -1;
            for (int k = parity; k < n; k += 2)
                if (contacts[k].time <= t) before = k;
            double stride = 2 * (contacts[n - 1].time - contacts[0].time) / (n - 1);
            double a, b;
            if (before < 0)
            {
                b = contacts[parity].time;
                a = b - stride;
            }
            else
            {
                a = contacts[before].time;
                b = before + 2 < n ? contacts[before + 2].time : a + stride;
            }
            double cycle = Math.Max(0, Math.Min(0.999999, (t - a) / (b - a)));
            return map.PhaseAtCycle(cycle, map.StanceShare(0.5 * (b - a)));
        }
    }
}
