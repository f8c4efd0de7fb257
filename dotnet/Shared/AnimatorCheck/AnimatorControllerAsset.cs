using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using YamlDotNet.RepresentationModel;

namespace HeadGait.Tooling
{
    /// <summary>A parameter of an Animator Controller (m_AnimatorParameters; m_Type 1 float, 3 int, 4 bool, 9 trigger).</summary>
    public sealed class ControllerParameter
    {
        public string Name;
        public int Type;
        public double Default;
    }

    /// <summary>A transition condition (AnimatorCondition: m_ConditionMode, m_ConditionEvent, m_EventTreshold).</summary>
    public sealed class ControllerCondition
    {
        public int Mode;
        public string Parameter;
        public double Threshold;
    }

    /// <summary>An AnimatorStateTransition as serialized (class 1101), with its source (null for Any State) and priority.</summary>
    public sealed class ControllerTransition
    {
        public long Id;
        public ControllerState Source;    // null: an Any State transition
        public ControllerState Destination;
        public int Priority;              // index in its list (the state's m_Transitions or m_AnyStateTransitions): 0 first
        public readonly List<ControllerCondition> Conditions = new List<ControllerCondition>();
        public bool Solo, Mute, IsExit;
        public double Duration, Offset, ExitTime;
        public bool HasExitTime, HasFixedDuration, OrderedInterruption, CanTransitionToSelf;
        public int InterruptionSource;    // TransitionInterruptionSource: 0 None, 1 Source, 2 Destination, 3 SourceThenDestination, 4 DestinationThenSource

        public override string ToString() => $"{Source?.Name ?? "Any State"} -> {Destination?.Name ?? "(none)"}";
    }

    /// <summary>An AnimatorState (class 1102): its clip's length, speed, motion-time parameter and outgoing transitions.</summary>
    public sealed class ControllerState
    {
        public long Id;
        public string Name;
        public double Speed = 1;
        public double ClipLength = 1;     // seconds; from the state's .anim (m_StopTime - m_StartTime)
        public bool ClipLoops;
        public string TimeParameter;      // m_TimeParameter when m_TimeParameterActive: the state's normalized time
        public readonly List<ControllerTransition> Transitions = new List<ControllerTransition>();

        public override string ToString() => Name;
    }

    /// <summary>
    /// The first layer of an Animator Controller (.controller, Unity's text YAML) read for <see cref="AnimatorLayerSimulator"/>:
    /// parameters, the layer's states and default state, Any State transitions and each state's transitions in their
    /// serialized (priority) order. Field names follow UnityCsReference Editor/Mono/Animation/StateMachine.bindings.cs
    /// (AnimatorStateTransition, AnimatorTransitionBase, AnimatorCondition, AnimatorState, AnimatorStateMachine) and
    /// Editor/Mono/Animation/AnimatorController.bindings.cs (parameters, layers). Sub-state machines and entry transitions
    /// are refused rather than guessed at (the package's controller has neither).
    /// </summary>
    public sealed class AnimatorControllerAsset
    {
        public readonly List<ControllerParameter> Parameters = new List<ControllerParameter>();
        public readonly List<ControllerState> States = new List<ControllerState>();
        public readonly List<ControllerTransition> AnyStateTransitions = new List<ControllerTransition>();
        public ControllerState DefaultState;

        public ControllerState State(string name) => States.FirstOrDefault(s => s.Name == name)
            ?? throw new InvalidOperationException($"the controller has no state '{name}'");

        /// <summary>Reads a controller file; clip lengths come from the .anim files (by GUID) found under <paramref name="clipFolder"/>.</summary>
        public static AnimatorControllerAsset Load(string path, string clipFolder = null)
        {
            var clips = new Dictionary<string, (double Length, bool Loops)>();
            if (clipFolder != null)
                foreach (var meta in Directory.GetFiles(clipFolder, "*.anim.meta", SearchOption.AllDirectories))
                {
                    string guid = File.ReadLines(meta).Select(l => l.Trim()).FirstOrDefault(l => l.StartsWith("guid:", StringComparison.Ordinal))?.Substring(5).Trim();
                    if (guid == null) continue;
                    var clip = UnityYamlFile.Parse(File.ReadAllText(meta.Substring(0, meta.Length - 5)), meta).FirstOrDefault(d => d.ClassId == 74);
                    if (clip?.Node("m_AnimationClipSettings") is YamlMappingNode settings)
                    {
                        double start = Number(Scalar(settings, "m_StartTime"), 0), stop = Number(Scalar(settings, "m_StopTime"), 1);
                        clips[guid] = (stop - start, Scalar(settings, "m_LoopTime") == "1");
                    }
                }
            return Parse(File.ReadAllText(path), path, clips);
        }

        public static AnimatorControllerAsset Parse(string text, string file, IReadOnlyDictionary<string, (double Length, bool Loops)> clips = null)
        {
            var docs = UnityYamlFile.Parse(text, file);
            var byId = docs.ToDictionary(d => d.FileId);
            var controller = docs.FirstOrDefault(d => d.ClassId == 91) ?? throw new FormatException($"{file}: no AnimatorController (class 91)");
            var asset = new AnimatorControllerAsset();
            if (controller.Node("m_AnimatorParameters") is YamlSequenceNode ps)
                foreach (YamlMappingNode p in ps.Children)
                {
                    int type = (int)Number(Scalar(p, "m_Type"), 0);
                    string def = type == 1 ? "m_DefaultFloat" : type == 3 ? "m_DefaultInt" : "m_DefaultBool";
                    asset.Parameters.Add(new ControllerParameter { Name = Scalar(p, "m_Name"), Type = type, Default = Number(Scalar(p, def), 0) });
                }
            if (!(controller.Node("m_AnimatorLayers") is YamlSequenceNode layers) || layers.Children.Count == 0)
                throw new FormatException($"{file}: the controller has no layer");
            long machineId = Ref(((YamlMappingNode)layers.Children[0]).Children[new YamlScalarNode("m_StateMachine")]);
            if (!byId.TryGetValue(machineId, out var machine) || machine.ClassId != 1107) throw new FormatException($"{file}: the first layer's state machine &{machineId} is missing");
            if (machine.Node("m_ChildStateMachines") is YamlSequenceNode subs && subs.Children.Count > 0)
                throw new FormatException($"{file}: sub-state machines are not simulated");
            if (machine.Node("m_EntryTransitions") is YamlSequenceNode entries && entries.Children.Count > 0)
                throw new FormatException($"{file}: entry transitions are not simulated");

            var stateById = new Dictionary<long, ControllerState>();
            foreach (YamlMappingNode child in ((YamlSequenceNode)machine.Node("m_ChildStates")).Children)
            {
                long id = Ref(child.Children[new YamlScalarNode("m_State")]);
                var s = byId[id];
                var state = new ControllerState
                {
                    Id = id,
                    Name = s.Scalar("m_Name"),
                    Speed = Number(s.Scalar("m_Speed"), 1),
                    TimeParameter = s.Scalar("m_TimeParameterActive") == "1" ? s.Scalar("m_TimeParameter") : null,
                };
                if (s.Node("m_Motion") is YamlMappingNode motion && Scalar(motion, "guid") is string g && clips != null && clips.TryGetValue(g, out var clip))
                {
                    state.ClipLength = clip.Length;
                    state.ClipLoops = clip.Loops;
                }
                stateById[id] = state;
                asset.States.Add(state);
            }
            asset.DefaultState = stateById.TryGetValue(Ref(machine.Node("m_DefaultState")), out var d) ? d : asset.States.FirstOrDefault();

            ControllerTransition Transition(long id, ControllerState source, int priority)
            {
                var t = byId[id];
                var tr = new ControllerTransition
                {
                    Id = id,
                    Source = source,
                    Priority = priority,
                    Destination = stateById.TryGetValue(Ref(t.Node("m_DstState")), out var dst) ? dst : null,
                    Solo = t.Scalar("m_Solo") == "1",
                    Mute = t.Scalar("m_Mute") == "1",
                    IsExit = t.Scalar("m_IsExit") == "1",
                    Duration = Number(t.Scalar("m_TransitionDuration"), 0),
                    Offset = Number(t.Scalar("m_TransitionOffset"), 0),
                    ExitTime = Number(t.Scalar("m_ExitTime"), 0),
                    HasExitTime = t.Scalar("m_HasExitTime") == "1",
                    HasFixedDuration = t.Scalar("m_HasFixedDuration") == "1",
                    InterruptionSource = (int)Number(t.Scalar("m_InterruptionSource"), 0),
                    OrderedInterruption = t.Scalar("m_OrderedInterruption") != "0",
                    CanTransitionToSelf = t.Scalar("m_CanTransitionToSelf") == "1",
                };
                if (tr.Destination == null && !tr.IsExit) throw new FormatException($"{file}: transition &{id} leads to no state of the layer");
                if (t.Node("m_Conditions") is YamlSequenceNode cs)
                    foreach (YamlMappingNode c in cs.Children)
                        tr.Conditions.Add(new ControllerCondition
                        {
                            Mode = (int)Number(Scalar(c, "m_ConditionMode"), 0),
                            Parameter = Scalar(c, "m_ConditionEvent"),
                            Threshold = Number(Scalar(c, "m_EventTreshold"), 0),
                        });
                return tr;
            }

            if (machine.Node("m_AnyStateTransitions") is YamlSequenceNode any)
                for (int i = 0; i < any.Children.Count; i++) asset.AnyStateTransitions.Add(Transition(Ref(any.Children[i]), null, i));
            foreach (var state in asset.States)
                if (byId[state.Id].Node("m_Transitions") is YamlSequenceNode list)
                    for (int i = 0; i < list.Children.Count; i++) state.Transitions.Add(Transition(Ref(list.Children[i]), state, i));
            return asset;
        }

        static string Scalar(YamlMappingNode m, string key) => m.Children.TryGetValue(new YamlScalarNode(key), out var n) && n is YamlScalarNode s ? s.Value ?? "" : null;

        static long Ref(YamlNode n) => n is YamlMappingNode m && Scalar(m, "fileID") is string id ? long.Parse(id, CultureInfo.InvariantCulture) : 0;

        static double Number(string s, double fallback) => double.TryParse(s, NumberStyles.Float, CultureInfo.InvariantCulture, out double v) ? v : fallback;
    }
}
