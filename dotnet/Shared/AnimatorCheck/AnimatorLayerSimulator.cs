using System;
using System.Collections.Generic;

namespace HeadGait.Tooling
{
    /// <summary>
    /// How Any State transitions meet a transition in progress: Unity's published material does not settle it, so the
    /// check runs the controller under both readings and a controller must pass both.
    /// </summary>
    public enum AnyStateReading
    {
        /// <summary>Any State transitions are evaluated every update, also during a transition whatever its interruption
        /// source (the reading behind the common "Any State restarts itself" reports when Can Transition To Self is on).</summary>
        AlwaysEvaluated,
        /// <summary>During a transition Any State transitions may interrupt only when its interruption source is not None.</summary>
        ObeyInterruptionSource,
    }

    /// <summary>
    /// One Animator layer run the way Unity's Animator runs it, for a controller read by <see cref="AnimatorControllerAsset"/>.
    /// Unity's state machine is native code (no C# source is published); each rule below names the published material it
    /// follows. Call <see cref="Update"/> once per frame after setting the parameters, as the Animator evaluates after the
    /// scripts' Update (Unity Manual, "Order of execution for event functions": the internal animation update runs between
    /// Update and LateUpdate).
    /// <list type="bullet">
    /// <item>A transition is taken when all its conditions hold and, with Has Exit Time, when the source state's normalized
    /// time reaches the exit time on this update (ScriptReference AnimatorStateTransition.exitTime: true on the first frame
    /// it is reached, below 1 once per loop, above 1 once). A transition with neither conditions nor exit time is ignored, as
    /// the editor warns. Muted transitions never run; when any transition of a list is solo, only solo ones do
    /// (AnimatorTransitionBase.solo / mute).</item>
    /// <item>Condition modes are AnimatorConditionMode (UnityCsReference Editor/Mono/Animation/StateMachine.bindings.cs: If 1,
    /// IfNot 2, Greater 3, Less 4, Equals 6, NotEqual 7); a trigger that a taken transition used is reset.</item>
    /// <item>Order: Any State transitions first, then the current state's, each list in its serialized order (the order
    /// the state's inspector shows, which is the transitions' priority: Unity blog "State Machine Transition interruptions",
    /// 2016, and Manual "Animation transitions"). At most one transition starts per layer and update.</item>
    /// <item>Any State transitions skip the state being shown (the current state, or the destination of the transition in
    /// progress) unless Can Transition To Self is on (AnimatorStateTransition.canTransitionToSelf).</item>
    /// <item>Duration: seconds with Has Fixed Duration, else a fraction of the source state's length (clip length / speed)
    /// (AnimatorStateTransition.hasFixedDuration, duration). The destination starts at the transition offset (normalized).
    /// The update that starts a transition does not advance it; it completes on the update where its elapsed time reaches
    /// the duration, so a blend of d seconds takes ceil(d * fps) updates after the one that started it. On that update an
    /// interruption that holds (see below) still starts, as on every update the transition runs; otherwise the new state's
    /// own transitions are first evaluated on the next update (conservative: it never shortens a measured lag).</item>
    /// <item>Interruption (TransitionInterruptionSource in StateMachine.bindings.cs; ScriptReference pages of its values; the
    /// 2016 blog): None: the transition runs to its end; Source: the source state's transitions may interrupt it, with
    /// Ordered Interruption only those listed before it; Destination: the destination state's transitions;
    /// SourceThenDestination / DestinationThenSource: both lists, the first named first. An interruption starts the new
    /// transition from the current blend at once. Any State transitions per <see cref="AnyStateReading"/>.</item>
    /// <item>A state whose Motion Time parameter is active takes its normalized time from that float parameter
    /// (AnimatorState.timeParameterActive / timeParameter); otherwise time runs at speed / clip length.</item>
    /// </list>
    /// </summary>
    public sealed class AnimatorLayerSimulator
    {
        /// <summary>Unity keeps time in single precision; sums of frame times that reach a duration in exact arithmetic
        /// must not miss it by a rounding error (six 1/60 s frames are 0.1 s).</summary>
        const double TimeTolerance = 1e-6;

        readonly AnimatorControllerAsset asset;
        readonly AnyStateReading reading;
        readonly Dictionary<string, double> values = new Dictionary<string, double>();
        readonly Dictionary<string, int> types = new Dictionary<string, int>();

        double currentTime, previousTime; // normalized time of Current
        ControllerTransition active;
        double elapsed, durationSeconds, nextTime;

        public AnimatorLayerSimulator(AnimatorControllerAsset asset, AnyStateReading reading = AnyStateReading.AlwaysEvaluated)
        {
            this.asset = asset ?? throw new ArgumentNullException(nameof(asset));
            this.reading = reading;
            foreach (var p in asset.Parameters)
            {
                values[p.Name] = p.Default;
                types[p.Name] = p.Type;
            }
            Current = asset.DefaultState ?? throw new InvalidOperationException("the controller's layer has no state");
        }

        /// <summary>The state the layer is in (the source while a transition runs).</summary>
        public ControllerState Current { get; private set; }

        /// <summary>The transition in progress, or null.</summary>
        public ControllerTransition Transition => active;

        /// <summary>What the avatar is heading for: the running transition's destination, else the current state.</summary>
        public ControllerState Shown => active != null ? active.Destination : Current;

        /// <summary>How far the running transition is (0..1); 1 outside transitions.</summary>
        public double TransitionProgress => active == null ? 1 : durationSeconds <= 0 ? 1 : Math.Min(1, elapsed / durationSeconds);

        /// <summary>Animator.SetInteger / SetFloat / SetBool / SetTrigger; an unknown name is ignored, as Unity ignores it
        /// (after logging that the parameter does not exist).</summary>
        public void Set(string name, double value)
        {
            if (values.ContainsKey(name)) values[name] = value;
        }

        /// <summary>One Animator update of <paramref name="dt"/> seconds.</summary>
        public void Update(double dt)
        {
            previousTime = currentTime;
            currentTime = TimeOf(Current, currentTime + dt * Current.Speed / Math.Max(1e-6, Current.ClipLength));
            if (active != null)
            {
                elapsed += dt;
                nextTime = TimeOf(active.Destination, nextTime + dt * active.Destination.Speed / Math.Max(1e-6, active.Destination.ClipLength));
                // An interruptible transition is interruptible on every update it runs, its last included.
                var interruption = FirstInterruption();
                if (interruption != null) Start(interruption);
                else if (elapsed >= durationSeconds - TimeTolerance) Finish();
                return;
            }
            var next = First(asset.AnyStateTransitions, Current, null) ?? First(Current.Transitions, Current, null);
            if (next != null) Start(next);
        }

        double TimeOf(ControllerState state, double advanced)
            => state.TimeParameter != null && values.TryGetValue(state.TimeParameter, out double t) ? t : advanced;

        ControllerTransition FirstInterruption()
        {
            int source = active.InterruptionSource;
            if (reading == AnyStateReading.AlwaysEvaluated || source != 0)
            {
                var any = First(asset.AnyStateTransitions, active.Destination, active);
                if (any != null) return any;
            }
            var from = active.Source ?? Current;
            ControllerTransition FromSource() => First(from.Transitions, null, active, active.OrderedInterruption && active.Source != null ? active.Priority : int.MaxValue);
            ControllerTransition FromDestination() => First(active.Destination.Transitions, null, active);
            switch (source)
            {
                case 1: return FromSource();
                case 2: return FromDestination();
                case 3: return FromSource() ?? FromDestination();
                case 4: return FromDestination() ?? FromSource();
                default: return null;
            }
        }

        /// <summary>The first transition of <paramref name="list"/> that may start now.</summary>
        /// <param name="self">For Any State transitions: the state shown, skipped unless Can Transition To Self.</param>
        /// <param name="running">The transition in progress: a state's transition never restarts itself nor another leading
        /// where it leads; an Any State one restarts itself only with Can Transition To Self.</param>
        /// <param name="before">Only transitions listed before this priority (Ordered Interruption).</param>
        ControllerTransition First(List<ControllerTransition> list, ControllerState self, ControllerTransition running, int before = int.MaxValue)
        {
            bool solo = list.Exists(t => t.Solo);
            foreach (var t in list)
            {
                if (t.Priority >= before) break;
                if (t.Mute || (solo && !t.Solo) || (t == running && t.Source != null) || t.IsExit) continue;
                if (t.Source == null && t.Destination == self && !t.CanTransitionToSelf) continue;
                if (running != null && t.Source != null && t.Destination == running.Destination) continue;
                if (t.Conditions.Count == 0 && !t.HasExitTime) continue;
                if (t.HasExitTime && !ExitTimeReached(t)) continue;
                if (t.Conditions.TrueForAll(Holds)) return t;
            }
            return null;
        }

        bool ExitTimeReached(ControllerTransition t)
        {
            double exit = t.ExitTime;
            if (exit >= 1 || !(t.Source ?? Current).ClipLoops) return previousTime < exit && currentTime >= exit;
            // Below 1 on a looping clip: once per loop.
            double a = previousTime - Math.Floor(previousTime), b = a + (currentTime - previousTime);
            return a < exit && b >= exit || b - 1 >= exit;
        }

        bool Holds(ControllerCondition c)
        {
            if (!values.TryGetValue(c.Parameter ?? "", out double v)) return false;
            switch (c.Mode)
            {
                case 1: return v != 0;
                case 2: return v == 0;
                case 3: return v > c.Threshold;
                case 4: return v < c.Threshold;
                case 6: return v == c.Threshold;
                case 7: return v != c.Threshold;
                default: return false;
            }
        }

        void Start(ControllerTransition t)
        {
            foreach (var c in t.Conditions)
                if (types.TryGetValue(c.Parameter ?? "", out int type) && type == 9) values[c.Parameter] = 0; // a trigger is consumed
            var from = active != null ? active.Destination : Current;
            active = t;
            elapsed = 0;
            durationSeconds = t.HasFixedDuration ? t.Duration : t.Duration * from.ClipLength / Math.Max(1e-6, Math.Abs(from.Speed));
            nextTime = TimeOf(t.Destination, t.Offset);
            if (durationSeconds <= 0) Finish();
        }

        void Finish()
        {
            Current = active.Destination;
            currentTime = previousTime = nextTime;
            active = null;
        }
    }
}
