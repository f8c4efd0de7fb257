using System;

namespace HeadGait
{
    /// <summary>The mannequin's pose in one frame of a clip: both legs, the hips' height and the arms' swing (degrees, + forward).</summary>
    public readonly struct BodyPose
    {
        public readonly LegAngles Left;
        public readonly LegAngles Right;
        public readonly double HipHeight;
        /// <summary>Anterior pelvic tilt, degrees (the hips' rotation, which the thighs and trunk inherit).</summary>
        public readonly double PelvicTilt;
        public readonly double LeftArm;
        public readonly double RightArm;

        public BodyPose(LegAngles left, LegAngles right, double hipHeight, double pelvicTilt, double leftArm, double rightArm)
        {
            Left = left;
            Right = right;
            HipHeight = hipHeight;
            PelvicTilt = pelvicTilt;
            LeftArm = leftArm;
            RightArm = rightArm;
        }

        public LegAngles Of(Foot foot) => foot == Foot.Left ? Left : Right;

        /// <summary>Height of the foot's lowest point above the ground, metres.</summary>
        public double FootHeight(Foot foot) => HipHeight + Leg(foot).Lowest;

        public LegPoints Leg(Foot foot) => Mannequin.Leg(Of(foot), PelvicTilt);
    }

    /// <summary>
    /// The six clips, one per <see cref="LocomotionState"/>, as functions of the stride position (0 = left initial contact):
    /// every moving state's normalized time is the core's stride position, so its feet land when the core says they do.
    /// Each leg follows <see cref="NormativeGait"/> in its own cycle (the right shifted by the phase map's right offset).
    /// The hips sit so that the foot that landed last touches the ground, which puts each initial contact exactly at the
    /// phase map's onset. Start clips blend from standing to walking over the step that ends with their foot's initial
    /// contact; finish clips blend from walking to standing over the step that ends with their foot's.
    /// </summary>
    public sealed class GaitClips
    {
        /// <summary>Arm swing, degrees of shoulder flexion per degree of the opposite hip's flexion.</summary>
        const double ArmSwing = 0.6;

        /// <summary>
        /// Anterior pelvic tilt while walking beyond that of quiet standing, degrees. The hip angles are relative to the
        /// pelvis, which walks tilted forward (Perry &amp; Burnfield 2010, ch. 9: mean anterior tilt with a few degrees of
        /// excursion); 3 deg puts both stance feet on the ground in double support with Winter's segment lengths (tested).
        /// </summary>
        public const double WalkingPelvicTilt = 3;

        public GaitClips(PhaseMap map)
        {
            Map = map ?? throw new ArgumentNullException(nameof(map));
        }

        public PhaseMap Map { get; }

        public static readonly LocomotionState[] All =
        {
            LocomotionState.Standing, LocomotionState.StartWalkLeft, LocomotionState.StartWalkRight,
            LocomotionState.Walking, LocomotionState.FinishWalkLeft, LocomotionState.FinishWalkRight,
        };

        /// <summary>The clip's (and its Animator state's) name: "Standing", "Start Walk Left", ...</summary>
        public static string Name(LocomotionState clip)
        {
            switch (clip)
            {
                case LocomotionState.Standing: return "Standing";
                case LocomotionState.StartWalkLeft: return "Start Walk Left";
                case LocomotionState.StartWalkRight: return "Start Walk Right";
                case LocomotionState.Walking: return "Walking";
                case LocomotionState.FinishWalkLeft: return "Finish Walk Left";
                case LocomotionState.FinishWalkRight: return "Finish Walk Right";
                default: throw new ArgumentOutOfRangeException(nameof(clip), clip, "not a locomotion state");
            }
        }

        /// <summary>Stride position of a foot's initial contact.</summary>
        public double InitialContact(Foot foot) => Map.StridePositionOfOnset(foot, GaitPhase.InitialContact);

        /// <summary>Stride position of a foot's toe-off (start of its initial swing).</summary>
        public double ToeOff(Foot foot) => Map.StridePositionOfOnset(foot, GaitPhase.InitialSwing);

        /// <summary>How much of the walking cycle the clip shows at a stride position (0 standing, 1 walking).</summary>
        public double WalkWeight(LocomotionState clip, double stridePosition)
        {
            double s = PhaseMap.Wrap(stridePosition);
            switch (clip)
            {
                case LocomotionState.Standing: return 0;
                case LocomotionState.Walking: return 1;
                case LocomotionState.StartWalkLeft: return Step(Foot.Left, s, out double t) ? Smooth(t) : 1;
                case LocomotionState.StartWalkRight: return Step(Foot.Right, s, out t) ? Smooth(t) : 1;
                case LocomotionState.FinishWalkLeft: return Step(Foot.Left, s, out t) ? 1 - Smooth(t) : 1;
                case LocomotionState.FinishWalkRight: return Step(Foot.Right, s, out t) ? 1 - Smooth(t) : 1;
                default: throw new ArgumentOutOfRangeException(nameof(clip), clip, "not a locomotion state");
            }
        }

        /// <summary>Is s inside the step that ends with the foot's initial contact, and how far through it (0..1)?</summary>
        bool Step(Foot foot, double s, out double t)
        {
            double end = InitialContact(foot);
            double start = InitialContact(foot == Foot.Left ? Foot.Right : Foot.Left);
            double length = PhaseMap.Wrap(end - start);
            double into = PhaseMap.Wrap(s - start);
            t = into / length;
            return into < length;
        }

        static double Smooth(double t) => t * t * (3 - 2 * t);

        /// <summary>The clip's pose at a stride position.</summary>
        public BodyPose Pose(LocomotionState clip, double stridePosition)
        {
            double s = PhaseMap.Wrap(stridePosition);
            double w = WalkWeight(clip, s);
            double offset = Map.RightOffset;
            var left = LegAngles.Lerp(NormativeGait.Standing, NormativeGait.At(Map, s), w);
            var right = LegAngles.Lerp(NormativeGait.Standing, NormativeGait.At(Map, s - offset), w);
            // The foot whose initial contact came last is on the ground (stance lasts longer than a step).
            bool leftLanded = PhaseMap.Wrap(s) <= PhaseMap.Wrap(s - offset);
            double tilt = w * WalkingPelvicTilt;
            double lowest = Mannequin.Leg(leftLanded ? left : right, tilt).Lowest;
            return new BodyPose(left, right, -lowest, tilt, ArmSwing * right.Hip, ArmSwing * left.Hip);
        }

        /// <summary>Height of a foot's lowest point above the ground in the clip at a stride position, metres.</summary>
        public double FootHeight(LocomotionState clip, Foot foot, double stridePosition) => Pose(clip, stridePosition).FootHeight(foot);
    }
}
