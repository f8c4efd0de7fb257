using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using HeadGait.Editor;
using HeadGait.Tooling;
using NUnit.Framework;
using UnityEditor;
using UnityEditor.Animations;
using UnityEngine;
using YamlDotNet.RepresentationModel;

namespace HeadGait.Tests
{
    /// <summary>
    /// Tools > HeadGait > Create Animator Controller builds, with Unity's editor API (here its stand-ins, which record what
    /// was built), the controller that `headgait clips` writes as YAML: the same parameters, layer, states, default state,
    /// transitions in the same priority order and every transition setting. Both read <see cref="LocomotionController"/>;
    /// this proves the editor path reads all of it and sets every field Unity would otherwise default.
    /// </summary>
    public class EditorControllerBuilderTests
    {
        const string Path = "Assets/HeadGait Test/HeadGait Legs.controller";

        static string Package => RepositoryPaths.Package;

        static Dictionary<LocomotionState, Motion> Clips()
            => LocomotionController.States.ToDictionary(s => s, s => (Motion)new AnimationClip { name = GaitClips.Name(s) });

        /// <summary>Builds the controller through the menu's builder and reads it back from the asset database.</summary>
        static AnimatorController Built(Dictionary<LocomotionState, Motion> clips = null)
        {
            LocomotionControllerBuilder.Create(Path, clips ?? Clips());
            return AssetDatabase.LoadAssetAtPath<AnimatorController>(Path) ?? throw new AssertionException("no controller at " + Path);
        }

        [TearDown]
        public void DeleteBuilt() => AssetDatabase.DeleteAsset(Path);

        /// <summary>
        /// The editor-built controller in the form the YAML reader gives (<see cref="AnimatorControllerAsset"/>), so one
        /// description and one simulator serve both. Clip lengths are the clips' (not the controller's): taken from
        /// <paramref name="clipsOf"/>'s state of the same name.
        /// </summary>
        static AnimatorControllerAsset Read(AnimatorController controller, AnimatorControllerAsset clipsOf)
        {
            var asset = new AnimatorControllerAsset();
            foreach (var p in controller.parameters)
                asset.Parameters.Add(new ControllerParameter
                {
                    Name = p.name,
                    Type = (int)p.type,
                    Default = p.type == AnimatorControllerParameterType.Float ? p.defaultFloat : p.type == AnimatorControllerParameterType.Int ? p.defaultInt : p.defaultBool ? 1 : 0,
                });
            var layers = controller.layers;
            Assert.That(layers.Length, Is.EqualTo(1), "one layer");
            var machine = layers[0].stateMachine;
            Assert.That(machine.entryTransitions, Is.Empty, "entry transitions are not simulated");
            var of = new Dictionary<AnimatorState, ControllerState>();
            long id = 1;
            foreach (var child in machine.states)
            {
                var s = child.state;
                var state = new ControllerState { Id = id++, Name = s.name, Speed = s.speed, TimeParameter = s.timeParameterActive ? s.timeParameter : null };
                var clip = clipsOf.States.FirstOrDefault(c => c.Name == s.name);
                if (clip != null)
                {
                    state.ClipLength = clip.ClipLength;
                    state.ClipLoops = clip.ClipLoops;
                }
                of[s] = state;
                asset.States.Add(state);
            }
            asset.DefaultState = machine.defaultState != null && of.TryGetValue(machine.defaultState, out var d) ? d : null;

            ControllerTransition Transition(AnimatorStateTransition t, ControllerState source, int priority)
            {
                var tr = new ControllerTransition
                {
                    Id = id++,
                    Source = source,
                    Priority = priority,
                    Destination = t.destinationState != null && of.TryGetValue(t.destinationState, out var dst) ? dst : null,
                    Solo = t.solo,
                    Mute = t.mute,
                    IsExit = t.isExit,
                    Duration = t.duration,
                    Offset = t.offset,
                    ExitTime = t.exitTime,
                    HasExitTime = t.hasExitTime,
                    HasFixedDuration = t.hasFixedDuration,
                    InterruptionSource = (int)t.interruptionSource,
                    OrderedInterruption = t.orderedInterruption,
                    CanTransitionToSelf = t.canTransitionToSelf,
                };
                foreach (var c in t.conditions)
                    tr.Conditions.Add(new ControllerCondition { Mode = (int)c.mode, Parameter = c.parameter, Threshold = c.threshold });
                return tr;
            }

            var any = machine.anyStateTransitions;
            for (int i = 0; i < any.Length; i++) asset.AnyStateTransitions.Add(Transition(any[i], null, i));
            foreach (var child in machine.states)
            {
                var list = child.state.transitions;
                for (int i = 0; i < list.Length; i++) of[child.state].Transitions.Add(Transition(list[i], of[child.state], i));
            }
            return asset;
        }

        /// <summary>Everything the Animator acts on, one line per parameter, state and transition (numbers as the float Unity stores).</summary>
        static List<string> Describe(AnimatorControllerAsset c)
        {
            static string F(double x) => ((float)x).ToString("R", CultureInfo.InvariantCulture);
            var lines = new List<string>();
            lines.AddRange(c.Parameters.Select(p => $"parameter {p.Name}: type {p.Type}, default {F(p.Default)}"));
            lines.Add($"default state {c.DefaultState?.Name}");
            lines.AddRange(c.States.Select(s => $"state {s.Name}: speed {F(s.Speed)}, time {s.TimeParameter ?? "-"}"));
            string T(ControllerTransition t)
                => $"{t} (priority {t.Priority}) when {string.Join(" and ", t.Conditions.Select(k => $"{k.Parameter} mode {k.Mode} {F(k.Threshold)}"))}: " +
                   $"duration {F(t.Duration)} fixed {t.HasFixedDuration}, exit time {t.HasExitTime} {F(t.ExitTime)}, offset {F(t.Offset)}, " +
                   $"interruption {t.InterruptionSource} ordered {t.OrderedInterruption}, to self {t.CanTransitionToSelf}, solo {t.Solo} mute {t.Mute} exit {t.IsExit}";
            lines.AddRange(c.AnyStateTransitions.Select(T));
            foreach (var s in c.States) lines.AddRange(s.Transitions.Select(T));
            return lines;
        }

        [Test]
        public void TheEditorBuiltControllerIsTheShippedOne()
        {
            var shipped = AnimatorControllerTests.Shipped();
            var clips = Clips();
            var built = Built(clips);
            var expected = Describe(shipped);
            Assert.That(expected.Count(l => l.Contains(" -> ")), Is.EqualTo(30), "the shipped controller: every state to every other");
            var actual = Describe(Read(built, shipped));
            Assert.That(actual.Except(expected), Is.Empty, "built by the editor, not in the shipped controller");
            Assert.That(expected.Except(actual), Is.Empty, "in the shipped controller, not built by the editor");
            Assert.That(actual, Is.EqualTo(expected), "in the same order (a state's transitions in priority order)");

            // The layer, the motions and where the Animator window draws the states, against the YAML itself.
            var docs = UnityYamlFile.Parse(File.ReadAllText(System.IO.Path.Combine(Package, GaitAssetFiles.Controller)), GaitAssetFiles.Controller);
            var byId = docs.ToDictionary(d => d.FileId);
            var machineDoc = docs.Single(d => d.ClassId == 1107);
            var layer = built.layers[0];
            Assert.That(layer.name, Is.EqualTo(machineDoc.Scalar("m_Name")));
            Assert.That(layer.stateMachine.name, Is.EqualTo(machineDoc.Scalar("m_Name")));
            var children = ((YamlSequenceNode)machineDoc.Node("m_ChildStates")).Children.Cast<YamlMappingNode>().ToList();
            var states = layer.stateMachine.states;
            Assert.That(states.Length, Is.EqualTo(children.Count));
            for (int i = 0; i < children.Count; i++)
            {
                var stateDoc = byId[long.Parse(((YamlScalarNode)((YamlMappingNode)children[i].Children[new YamlScalarNode("m_State")]).Children[new YamlScalarNode("fileID")]).Value, CultureInfo.InvariantCulture)];
                var position = (YamlMappingNode)children[i].Children[new YamlScalarNode("m_Position")];
                string Axis(string a) => ((YamlScalarNode)position.Children[new YamlScalarNode(a)]).Value;
                Assert.That(states[i].state.name, Is.EqualTo(stateDoc.Scalar("m_Name")));
                Assert.That(states[i].position.x.ToString(CultureInfo.InvariantCulture), Is.EqualTo(Axis("x")), states[i].state.name);
                Assert.That(states[i].position.y.ToString(CultureInfo.InvariantCulture), Is.EqualTo(Axis("y")), states[i].state.name);
                Assert.That(states[i].state.writeDefaultValues ? "1" : "0", Is.EqualTo(stateDoc.Scalar("m_WriteDefaultValues")), states[i].state.name);
                var state = LocomotionController.States.Single(s => GaitClips.Name(s) == states[i].state.name);
                Assert.That(states[i].state.motion, Is.SameAs(clips[state]), "each state plays the clip given for it");
            }
        }

        [Test]
        public void TheComparisonSeesEveryChangedSettingAndAMissingTransition()
        {
            // The check above must not pass a controller that differs: each field of one transition changed in turn, then
            // one transition removed, is seen.
            var shipped = AnimatorControllerTests.Shipped();
            var expected = Describe(shipped);
            var changes = new (string What, Action<AnimatorStateTransition> Change)[]
            {
                ("duration", t => t.duration = 0.25f),
                ("fixed duration", t => t.hasFixedDuration = false),
                ("exit time", t => t.hasExitTime = true),
                ("exit time value", t => t.exitTime = 0.75f),
                ("offset", t => t.offset = 0.5f),
                ("interruption source", t => t.interruptionSource = TransitionInterruptionSource.Source),
                ("ordered interruption", t => t.orderedInterruption = false),
                ("can transition to self", t => t.canTransitionToSelf = true),
                ("condition", t => t.conditions = new[] { new AnimatorCondition { mode = AnimatorConditionMode.Greater, parameter = AnimatorParameters.State, threshold = 2 } }),
            };
            foreach (var (what, change) in changes)
            {
                var built = Built();
                change(built.layers[0].stateMachine.states[3].state.transitions[1]);
                Assert.That(Describe(Read(built, shipped)), Is.Not.EqualTo(expected), what);
            }
            var pruned = Built();
            var walking = pruned.layers[0].stateMachine.states.Single(c => c.state.name == GaitClips.Name(LocomotionState.Walking)).state;
            walking.transitions = walking.transitions.Skip(1).ToArray();
            Assert.That(Describe(Read(pruned, shipped)), Is.Not.EqualTo(expected), "a missing transition");
        }

        [Test]
        public void TheEditorBuiltControllerShowsEveryGeneratedWalkStartAndStop([Values(60, 72, 90, 120)] int fps)
        {
            // The Animator evaluator (dotnet/Shared/AnimatorCheck) on the editor-built controller, as on the shipped one.
            var controller = Read(Built(), AnimatorControllerTests.Shipped());
            AnimatorControllerTests.CheckEveryStartAndStop(TestData.EvalSet().Concat(TestData.Training).ToList(), fps, AnyStateReading.AlwaysEvaluated, controller);
        }

        [Test]
        public void TheCoresInterruptionSourcesAreUnitysByNameAndValue()
        {
            foreach (TransitionInterruption source in Enum.GetValues(typeof(TransitionInterruption)))
            {
                var unity = LocomotionControllerBuilder.Interruption(source);
                Assert.That(unity.ToString(), Is.EqualTo(source.ToString()));
                Assert.That((int)unity, Is.EqualTo((int)source));
            }
        }
    }
}
