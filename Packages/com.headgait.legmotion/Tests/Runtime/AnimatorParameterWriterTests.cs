using System.Collections.Generic;
using System.Reflection;
using HeadGait.Unity;
using NUnit.Framework;
using UnityEngine;

namespace HeadGait.Tests
{
    /// <summary>
    /// How <see cref="GaitLegAnimator"/> writes the Animator: only parameters the controller has (a missing one made Unity
    /// log "Parameter does not exist" every frame), by hashed id, and before the Animator evaluates.
    /// </summary>
    public class AnimatorParameterWriterTests
    {
        sealed class RecordingSink : IAnimatorParameterSink
        {
            public readonly List<(int id, float value)> Writes = new List<(int, float)>();
            public void SetInteger(int id, int value) => Writes.Add((id, value));
            public void SetFloat(int id, float value) => Writes.Add((id, value));
        }

        static AnimatorControllerParameter P(string name, AnimatorControllerParameterType type)
            => new AnimatorControllerParameter { name = name, type = type };

        static AnimatorParameterWriter Writer(params AnimatorControllerParameter[] controller)
            => new AnimatorParameterWriter(controller, AnimatorParameters.State, AnimatorParameters.StridePhase,
                AnimatorParameters.WalkWeight, AnimatorParameters.StepPeriod);

        static readonly AnimatorFrame Walking = new AnimatorFrame(3.0, LocomotionState.Walking, 0.25, GaitPhase.MidStance,
            GaitPhase.MidSwing, 0.8, 0.55, false);

        [Test]
        public void AParameterTheControllerLacksIsNeverWritten()
        {
            var writer = Writer(P(AnimatorParameters.State, AnimatorControllerParameterType.Int),
                P(AnimatorParameters.StridePhase, AnimatorControllerParameterType.Float),
                P(AnimatorParameters.WalkWeight, AnimatorControllerParameterType.Float));
            var sink = new RecordingSink();
            for (int frame = 0; frame < 100; frame++) writer.Write(Walking, sink);

            int stepPeriod = Animator.StringToHash(AnimatorParameters.StepPeriod);
            Assert.That(sink.Writes.Exists(w => w.id == stepPeriod), Is.False, "StepPeriod written to a controller without it");
            Assert.That(sink.Writes.Count, Is.EqualTo(300));
            Assert.That(writer.Count, Is.EqualTo(3));
            Assert.That(writer.Problem, Does.Contain(AnimatorParameters.StepPeriod), "the missing parameter is reported (once, by the component)");
        }

        [Test]
        public void ParametersAreWrittenByHashedIdWithTheFramesValues()
        {
            var writer = Writer(P(AnimatorParameters.State, AnimatorControllerParameterType.Int),
                P(AnimatorParameters.StridePhase, AnimatorControllerParameterType.Float),
                P(AnimatorParameters.WalkWeight, AnimatorControllerParameterType.Float),
                P(AnimatorParameters.StepPeriod, AnimatorControllerParameterType.Float));
            var sink = new RecordingSink();
            writer.Write(Walking, sink);

            Assert.That(writer.Problem, Is.Null);
            Assert.That(sink.Writes, Is.EquivalentTo(new[]
            {
                (Animator.StringToHash(AnimatorParameters.State), (float)(int)LocomotionState.Walking),
                (Animator.StringToHash(AnimatorParameters.StridePhase), 0.25f),
                (Animator.StringToHash(AnimatorParameters.WalkWeight), 0.8f),
                (Animator.StringToHash(AnimatorParameters.StepPeriod), 0.55f),
            }));
        }

        [Test]
        public void AParameterOfAnotherTypeIsNotWritten()
        {
            var writer = Writer(P(AnimatorParameters.State, AnimatorControllerParameterType.Float),
                P(AnimatorParameters.StridePhase, AnimatorControllerParameterType.Float));
            var sink = new RecordingSink();
            writer.Write(Walking, sink);
            Assert.That(sink.Writes.Count, Is.EqualTo(1));
            Assert.That(writer.Problem, Does.Contain(AnimatorParameters.State).And.Contain("Float"));
        }

        [Test]
        public void AnEmptyNameIsNotWrittenNorReported()
        {
            var writer = new AnimatorParameterWriter(new[] { P(AnimatorParameters.State, AnimatorControllerParameterType.Int) },
                AnimatorParameters.State, "", null, "");
            Assert.That(writer.Problem, Is.Null);
            Assert.That(writer.Count, Is.EqualTo(1));
        }

        [Test]
        public void ParametersAreWrittenInUpdateBeforeTheAnimatorEvaluates()
        {
            // Unity evaluates Animators after every script's Update and before LateUpdate: values set in LateUpdate reach
            // the avatar a frame late. The component must write in Update, ordered after the default-order sources.
            const BindingFlags any = BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.DeclaredOnly;
            var type = typeof(GaitLegAnimator);
            Assert.That(type.GetMethod("Update", any), Is.Not.Null);
            Assert.That(type.GetMethod("LateUpdate", any), Is.Null, "parameters written after the Animator evaluated");
            var order = type.GetCustomAttribute<DefaultExecutionOrder>();
            Assert.That(order, Is.Not.Null);
            Assert.That(order.order, Is.GreaterThan(0), "runs after sources that push samples in their own Update");
        }
    }
}
