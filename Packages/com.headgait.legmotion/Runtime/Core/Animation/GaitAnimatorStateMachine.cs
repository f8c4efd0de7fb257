using System;
using System.Collections.Generic;

namespace HeadGait
{
    /// <summary>Animator states, one per clip family of the avatar's lower body.</summary>
    public enum LocomotionState
    {
        Standing = 0,
        StartWalkLeft = 1,
        StartWalkRight = 2,
        Walking = 3,
        FinishWalkLeft = 4,
        FinishWalkRight = 5,
    }

    public sealed class AnimatorSettings
    {
        /// <summary>How many of the latest predictions are smoothed (5 in the paper).</summary>
        public int HistoryLength = 5;

        /// <summary>Consecutive predictions that disagree with the animator before it changes course (3 in the paper).</summary>
        public int ConsecutiveErrorsToSwitch = 3;

        /// <summary>A walking prediction within this stride fraction of the animator's own position agrees with it.</summary>
        public double PhaseTolerance = 0.08;

        /// <summary>Share of the smoothed phase error removed per update while predictions agree (keeps the loop locked).</summary>
        public double Correction = 0.15;

        /// <summary>Seconds over which the animator blends to a new phase after it gave up on its own.</summary>
        public double BlendTime = 0.1;

        /// <summary>
        /// Share of its pace the clock keeps while it takes in a phase that lies behind it past a foot's contact or toe-off.
        /// Stepping the clock back over either would land that foot twice (the other foot's phase, half a stride back, where
        /// a classifier picks a held walk up again or flips its feet): it steps back only as far as neither foot changes
        /// between swing and stance, and runs at this share of its pace until the rest is taken in. Not fitted: half (on
        /// the glasses, `realworld`, avatar: alternating feet THR / COR / SVM / BLSTM 95.1 / 94.0 / 93.1 / 89.7 to 97.8 /
        /// 97.0 / 96.4 / 95.6 %, walking shown unchanged).
        /// </summary>
        public double CatchUpPace = 0.5;

        /// <summary>Step period used until predictions provide one (seconds).</summary>
        public double DefaultStepPeriod = 0.55;

        /// <summary>Longest Start/Finish clip, in step periods, before the state is forced on.</summary>
        public double MaxTransitionSteps = 1.5;

        /// <summary>
        /// Standing is recognised late (the window still holds the last step). If a foot landed within this stride
        /// fraction before the Finish begins, that foot closed the gait and the avatar settles where it is
        /// (for BlendTime) instead of taking another step.
        /// </summary>
        public double FinishLookBack = 0.3;

        /// <summary>
        /// A walk is recognised a few predictions after it begins. If a foot landed within this stride fraction before the
        /// Start begins, the Start rewinds to just before that contact, so the avatar lands the lead foot (starting after
        /// it would plant the foot straight from standing, without a step).
        /// </summary>
        public double StartLookBack = 0.03;
    }

    /// <summary>What the avatar's legs should show after one update.</summary>
    public readonly struct AnimatorFrame
    {
        public readonly double Time;
        public readonly LocomotionState State;
        /// <summary>Stride position driving the walking clips (0 = left initial contact).</summary>
        public readonly double StridePosition;
        public readonly GaitPhase Left;
        public readonly GaitPhase Right;
        /// <summary>Weight of the walking clips against the standing pose, 0..1.</summary>
        public readonly double WalkWeight;
        public readonly double StepPeriod;
        /// <summary>True on the update where the animator gave up its own phase for the predicted one.</summary>
        public readonly bool Resynchronised;

        public AnimatorFrame(double time, LocomotionState state, double stridePosition, GaitPhase left, GaitPhase right, double walkWeight, double stepPeriod, bool resynchronised)
        {
            Time = time;
            State = state;
            StridePosition = stridePosition;
            Left = left;
            Right = right;
            WalkWeight = walkWeight;
            StepPeriod = stepPeriod;
            Resynchronised = resynchronised;
        }

        /// <summary>The standing pose at <paramref name="time"/> (a stream's start, or after a gap or re-base).</summary>
        public static AnimatorFrame Standing(double time)
            => new AnimatorFrame(time, LocomotionState.Standing, 0, GaitPhase.Standing, GaitPhase.Standing, 0, 0, false);

        public GaitPhase PhaseOf(Foot foot) => foot == Foot.Left ? Left : Right;

        public override string ToString() => $"t={Time:F3} {State} s={StridePosition:F3} L={GaitPhases.ShortName(Left)} R={GaitPhases.ShortName(Right)} w={WalkWeight:F2}";
    }

    /// <summary>
    /// The avatar's lower-body state machine. It runs its own stride clock and follows the classifier
    /// through the smoothed last 5 predictions, but only changes course (start, finish, or jump to a new
    /// phase) after 3 consecutive predictions disagree with it, so single misclassifications never reach
    /// the avatar.
    /// <list type="bullet">
    /// <item>Standing -> Start Walk Left/Right: the foot that lands first (the one in swing) names the clip.</item>
    /// <item>Start Walk X -> Walking: once foot X's initial contact is reached.</item>
    /// <item>Walking -> Finish Walk Left/Right: the foot that lands next closes the gait.</item>
    /// <item>Finish Walk X -> Standing: once foot X has landed; -> Walking again if walking resumes.</item>
    /// </list>
    /// </summary>
    public sealed class GaitAnimatorStateMachine
    {
        readonly AnimatorSettings settings;
        readonly PhaseMap map;
        readonly StanceLatch stance = new StanceLatch();
        readonly List<GaitPrediction> history = new List<GaitPrediction>();

        LocomotionState state = LocomotionState.Standing;
        double s;
        double stepPeriod;
        double lastTime = double.NaN;
        int wrongRun;
        double blendRemaining;   // stride fraction still to blend in
        double blendTimeLeft;
        double lagRemaining;     // stride fraction (<= 0) still to fall back by running slower, not stepping back over a contact
        double transitionTarget; // stride position that ends a Start/Finish clip
        double transitionElapsed;
        double transitionStartS;
        bool settling;           // Finish: the closing foot has already landed; hold the pose, then stand

        public GaitAnimatorStateMachine(PhaseMap phaseMap = null, AnimatorSettings settings = null)
        {
            this.settings = settings ?? new AnimatorSettings();
            if (this.settings.HistoryLength < 1 || this.settings.ConsecutiveErrorsToSwitch < 1)
                throw new ArgumentException("HistoryLength and ConsecutiveErrorsToSwitch must be at least 1.");
            map = phaseMap ?? PhaseMap.Perry;
            stepPeriod = this.settings.DefaultStepPeriod;
        }

        public LocomotionState State => state;
        public double StridePosition => s;
        public AnimatorSettings Settings => settings;

        public void Reset()
        {
            history.Clear();
            state = LocomotionState.Standing;
            s = 0;
            stepPeriod = settings.DefaultStepPeriod;
            lastTime = double.NaN;
            wrongRun = 0;
            blendRemaining = 0;
            blendTimeLeft = 0;
            lagRemaining = 0;
            settling = false;
            stance.Reset();
        }

        static bool BelievesWalking(LocomotionState st)
            => st == LocomotionState.Walking || st == LocomotionState.StartWalkLeft || st == LocomotionState.StartWalkRight;

        public AnimatorFrame Update(GaitPrediction p)
        {
            double dt = double.IsNaN(lastTime) ? 0 : p.Time - lastTime;
            if (!(dt >= 0)) dt = 0;
            if (dt > 0.25) dt = 0.25; // a stalled stream must not fling the clock around
            lastTime = p.Time;

            history.Add(p);
            if (history.Count > settings.HistoryLength) history.RemoveAt(0);
            if (p.IsWalking && p.StepPeriod > 0) stepPeriod = 0.9 * stepPeriod + 0.1 * p.StepPeriod;

            // Advance the animator's own clock.
            double before = s;
            if (state != LocomotionState.Standing && !settling)
            {
                double advance = dt / (2 * stepPeriod);
                if (lagRemaining < 0)
                {
                    double taken = Math.Min(-lagRemaining, (1 - settings.CatchUpPace) * advance);
                    lagRemaining += taken;
                    advance -= taken;
                }
                s = PhaseMap.Wrap(s + advance);
                if (blendTimeLeft > 0)
                {
                    double part = blendTimeLeft <= dt ? blendRemaining : blendRemaining * dt / blendTimeLeft;
                    s = PhaseMap.Wrap(s + part);
                    blendRemaining -= part;
                    blendTimeLeft = Math.Max(0, blendTimeLeft - dt);
                }
            }

            bool walkingBelief = BelievesWalking(state);
            // While blending, the animator is already committed to where the blend ends.
            double committed = Committed;
            bool wrong = walkingBelief
                ? !p.IsWalking || Math.Abs(PhaseMap.CyclicDelta(p.StridePosition, committed)) > settings.PhaseTolerance
                : p.IsWalking;
            wrongRun = wrong ? wrongRun + 1 : 0;

            bool smoothedWalking = SmoothedWalking(p.Time, history.Count, out double smoothedS);
            bool resync = false;

            if (wrongRun >= settings.ConsecutiveErrorsToSwitch)
            {
                // Change course towards what the disagreeing predictions say, not the older agreeing ones,
                // and only if they agree among themselves (scattered phases are noise, not a new gait).
                SmoothedWalking(p.Time, settings.ConsecutiveErrorsToSwitch, out double wrongS);
                bool coherent = Coherent(p.Time, settings.ConsecutiveErrorsToSwitch, wrongS);
                int walkingVotes = 0;
                for (int i = history.Count - settings.ConsecutiveErrorsToSwitch; i < history.Count; i++)
                    if (i >= 0 && history[i].IsWalking) walkingVotes++;
                bool recentWalking = 2 * walkingVotes > settings.ConsecutiveErrorsToSwitch;
                if (!walkingBelief && recentWalking && !coherent)
                {
                    // Not yet: keep counting, the next coherent triple decides.
                    wrongRun = settings.ConsecutiveErrorsToSwitch - 1;
                }
                else if (!walkingBelief && recentWalking)
                {
                    if (state == LocomotionState.Standing)
                    {
                        s = wrongS;
                        if (LastFootToLand(s, out _, out double landedAgo) && landedAgo <= settings.StartLookBack)
                            s = PhaseMap.Wrap(s - landedAgo - StartLead);
                        Foot lead = NextFootToLand(s, out double target);
                        Enter(lead == Foot.Left ? LocomotionState.StartWalkLeft : LocomotionState.StartWalkRight, target);
                    }
                    else
                    {
                        settling = false;
                        BlendTo(wrongS);
                        state = LocomotionState.Walking;
                    }
                    resync = true;
                }
                else if (walkingBelief && !recentWalking)
                {
                    if (state == LocomotionState.Walking)
                    {
                        Foot closing;
                        double target;
                        if (LastFootToLand(s, out Foot landed, out double ago) && ago <= settings.FinishLookBack)
                        {
                            closing = landed;
                            target = s;
                            settling = true;
                        }
                        else
                        {
                            closing = NextFootToLand(s, out target);
                        }
                        Enter(closing == Foot.Left ? LocomotionState.FinishWalkLeft : LocomotionState.FinishWalkRight, target);
                    }
                    else
                    {
                        // Contradicted before the lead foot landed: cancel the start, back to standing.
                        state = LocomotionState.Standing;
                    }
                }
                else if (walkingBelief && coherent)
                {
                    BlendTo(wrongS);
                    resync = true;
                }
                if (wrongRun >= settings.ConsecutiveErrorsToSwitch) wrongRun = 0;
            }
            else if (walkingBelief && !wrong && smoothedWalking && blendTimeLeft <= 0)
            {
                double toward = settings.Correction * PhaseMap.CyclicDelta(smoothedS, Committed);
                if (toward >= 0 && lagRemaining < 0)
                {
                    double freed = Math.Min(toward, -lagRemaining);
                    lagRemaining += freed;
                    toward -= freed;
                }
                s = PhaseMap.Wrap(s + BackOverNoContact(toward));
            }

            // Start and Finish clips end when their foot lands (or after a bounded time).
            if (state != LocomotionState.Standing && state != LocomotionState.Walking && !resync)
            {
                transitionElapsed += dt;
                bool landed = settling ? transitionElapsed >= settings.BlendTime : Passed(before, s, transitionTarget);
                bool overdue = transitionElapsed > settings.MaxTransitionSteps * stepPeriod;
                if (landed || overdue)
                {
                    settling = false;
                    if (state == LocomotionState.StartWalkLeft || state == LocomotionState.StartWalkRight) state = LocomotionState.Walking;
                    else state = LocomotionState.Standing;
                }
            }

            return Frame(p.Time, resync);
        }

        /// <summary>How far before the lead foot's contact a rewound Start begins (stride fraction; about 10 ms).</summary>
        const double StartLead = 0.01;

        AnimatorFrame Frame(double time, bool resync)
        {
            if (state == LocomotionState.Standing)
            {
                stance.Reset();
                return new AnimatorFrame(time, state, s, GaitPhase.Standing, GaitPhase.Standing, 0, stepPeriod, resync);
            }
            double weight = 1;
            if (settling)
            {
                weight = 1 - Math.Min(1, transitionElapsed / Math.Max(1e-6, settings.BlendTime));
            }
            else if (state != LocomotionState.Walking)
            {
                double total = PhaseMap.Wrap(transitionTarget - transitionStartS);
                double done = total > 1e-6 ? Math.Min(1, PhaseMap.Wrap(s - transitionStartS) / total) : 1;
                if (PhaseMap.Wrap(s - transitionStartS) > 0.75) done = 0; // blended slightly backwards
                bool starting = state == LocomotionState.StartWalkLeft || state == LocomotionState.StartWalkRight;
                weight = starting ? done : 1 - done;
            }
            return new AnimatorFrame(time, state, s, stance.PhaseAt(map, Foot.Left, s, stepPeriod), stance.PhaseAt(map, Foot.Right, s, stepPeriod), weight, stepPeriod, resync);
        }

        void Enter(LocomotionState next, double target)
        {
            state = next;
            transitionTarget = target;
            transitionStartS = s;
            transitionElapsed = 0;
        }

        /// <summary>Where the clock is headed: its position with the blend under way and the lag still to take in.</summary>
        double Committed => PhaseMap.Wrap(s + (blendTimeLeft > 0 ? blendRemaining : 0) + lagRemaining);

        void BlendTo(double target)
        {
            lagRemaining = 0;
            blendRemaining = BackOverNoContact(PhaseMap.CyclicDelta(target, s));
            blendTimeLeft = settings.BlendTime;
            if (blendTimeLeft <= 0)
            {
                s = PhaseMap.Wrap(s + blendRemaining);
                blendRemaining = 0;
            }
        }

        /// <summary>
        /// The part of a move of the clock by <paramref name="delta"/> (stride fraction) that it may make at once: all of a
        /// forward move (and of a step back of nearly half a stride, taken forward: <see cref="OtherFootBehind"/>), and of a
        /// step back the part over which neither foot goes between swing and stance. Back over a
        /// contact the foot would land again, back over a toe-off it would drop from swing to the ground: both count as a
        /// contact of that foot, twice in a row. The rest is left to <see cref="lagRemaining"/> (taken in at
        /// <see cref="AnimatorSettings.CatchUpPace"/>).
        /// </summary>
        double BackOverNoContact(double delta)
        {
            if (delta >= 0) return delta;
            if (delta < -OtherFootBehind) return delta + 1;
            bool left = InStance(Foot.Left, s), right = InStance(Foot.Right, s);
            double clear = 0;
            for (double back = BackStep; back <= -delta + BackStep; back += BackStep)
            {
                double x = PhaseMap.Wrap(s - Math.Min(back, -delta));
                if (InStance(Foot.Left, x) != left || InStance(Foot.Right, x) != right) break;
                clear = Math.Min(back, -delta);
            }
            if (clear >= -delta) return delta;
            double allowed = Math.Max(0, clear - BackStep);
            lagRemaining += delta + allowed;
            return -allowed;
        }

        /// <summary>
        /// Whether the foot stands at stride position x as the frames show it: with the stance share it latched at its last
        /// contact (<see cref="StanceLatch"/>), not the map's share at today's period. Checked against the map's, a step back
        /// crossed a latched toe-off the map put a little earlier, and the foot landed twice in 0.05 s (SVM on the glasses).
        /// </summary>
        bool InStance(Foot foot, double x) => GaitPhases.IsStance(stance.PhaseWithHeldShare(map, foot, x, stepPeriod));

        /// <summary>
        /// A phase further behind the clock than this (stride fraction) is within a tenth of a step of half a stride: the
        /// other foot's phase, as much ahead as behind, and the clock goes forward to it (passing the feet's events in
        /// order) rather than falling back most of a step. Looked at on the glasses (`realworld`, avatar, THR / COR / SVM /
        /// BLSTM; steps per step of the signal, alternating feet): none 1.02 / 1.00 / 0.92 / 0.90, 97.8 / 97.0 / 96.4 /
        /// 95.6 %; 0.45: 1.03 / 1.03 / 0.96 / 0.96, 97.9 / 97.2 / 96.8 / 96.2 %; 0.4: 1.05 / 1.07 / 1.01 / 1.06, 97.9 /
        /// 97.4 / 96.9 / 96.8 %.
        /// </summary>
        const double OtherFootBehind = 0.45;

        /// <summary>Resolution (stride fraction; about 5 ms) at which a step back is checked, and its margin before a foot's event (the feet's stance shares are latched, and may differ a little from the map's).</summary>
        const double BackStep = 0.005;

        /// <summary>The foot whose initial contact comes next from stride position x, and where it lands.</summary>
        Foot NextFootToLand(double x, out double target)
        {
            double left = map.StridePositionOfOnset(Foot.Left, GaitPhase.InitialContact);
            double right = map.StridePositionOfOnset(Foot.Right, GaitPhase.InitialContact);
            double dl = PhaseMap.Wrap(left - x), dr = PhaseMap.Wrap(right - x);
            if (dl <= dr)
            {
                target = left;
                return Foot.Left;
            }
            target = right;
            return Foot.Right;
        }

        /// <summary>The foot whose initial contact was passed most recently before stride position x, and how long ago (stride fraction).</summary>
        bool LastFootToLand(double x, out Foot foot, out double ago)
        {
            double left = PhaseMap.Wrap(x - map.StridePositionOfOnset(Foot.Left, GaitPhase.InitialContact));
            double right = PhaseMap.Wrap(x - map.StridePositionOfOnset(Foot.Right, GaitPhase.InitialContact));
            foot = left <= right ? Foot.Left : Foot.Right;
            ago = Math.Min(left, right);
            return true;
        }

        /// <summary>Did the clock pass the target going forward from a to b (a short forward move)?</summary>
        static bool Passed(double a, double b, double target)
        {
            double moved = PhaseMap.Wrap(b - a);
            if (moved > 0.5) return false; // went backwards (blend)
            double toTarget = PhaseMap.Wrap(target - a);
            return toTarget > 0 && toTarget <= moved || (moved > 0 && Math.Abs(PhaseMap.CyclicDelta(b, target)) < 1e-9);
        }

        /// <summary>Do the latest walking predictions, advanced to now, lie within the phase tolerance of their mean?</summary>
        bool Coherent(double now, int count, double mean)
        {
            for (int i = Math.Max(0, history.Count - count); i < history.Count; i++)
            {
                var h = history[i];
                if (!h.IsWalking) continue;
                double period = h.StepPeriod > 0 ? h.StepPeriod : stepPeriod;
                double x = h.StridePosition + (now - h.Time) / (2 * period);
                if (Math.Abs(PhaseMap.CyclicDelta(x, mean)) > settings.PhaseTolerance) return false;
            }
            return true;
        }

        /// <summary>
        /// Majority vote of the latest <paramref name="count"/> predictions for walking, and the circular mean of
        /// the walking ones' stride positions, each advanced to now.
        /// </summary>
        bool SmoothedWalking(double now, int count, out double position)
        {
            int votes = 0, considered = 0;
            double cx = 0, cy = 0;
            for (int i = Math.Max(0, history.Count - count); i < history.Count; i++)
            {
                var h = history[i];
                considered++;
                if (!h.IsWalking) continue;
                votes++;
                double period = h.StepPeriod > 0 ? h.StepPeriod : stepPeriod;
                double x = h.StridePosition + (now - h.Time) / (2 * period);
                cx += Math.Cos(2 * Math.PI * x);
                cy += Math.Sin(2 * Math.PI * x);
            }
            position = votes > 0 ? PhaseMap.Wrap(Math.Atan2(cy, cx) / (2 * Math.PI)) : s;
            return 2 * votes > considered;
        }
    }
}
