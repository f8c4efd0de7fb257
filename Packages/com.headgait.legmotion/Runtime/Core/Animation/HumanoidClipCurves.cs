using System;
using System.Collections.Generic;

namespace HeadGait
{
    /// <summary>One float curve of a Humanoid gait clip on the Animator (path ""): a muscle or a root curve, keyed at its clip's keys.</summary>
    public sealed class HumanoidClipCurve
    {
        /// <summary>The Animator's curve name: a muscle ("Left Upper Leg Front-Back") or RootT.x/y/z, RootQ.x/y/z/w.</summary>
        public string Attribute;
        /// <summary>[key]: value and one-sided slopes per second of clip time.</summary>
        public double[] Values, InSlopes, OutSlopes;

        /// <summary>A curve that never changes needs only its first and last key.</summary>
        public bool IsConstant
        {
            get
            {
                for (int k = 0; k < Values.Length; k++)
                    if (Math.Abs(Values[k] - Values[0]) >= 1e-9 || InSlopes[k] != 0 || OutSlopes[k] != 0) return false;
                return true;
            }
        }
    }

    /// <summary>
    /// The keyed curves of one of <see cref="GaitClips"/> as a Humanoid clip, for the developer's own avatar: muscle values
    /// (<see cref="HumanoidMuscles"/>) and the body's root curves RootT.x/y/z (body position in the avatar's normalized human
    /// scale: standing = 1) and RootQ.x/y/z/w (body rotation: the pelvic tilt), all float curves on the Animator with an
    /// empty path, at the keys of <see cref="GaitClipCurves"/>. One place for what `headgait clips` writes as the Humanoid
    /// .anim files and what Tools > HeadGait > Create Humanoid Clips sets with AnimationUtility.SetEditorCurve. The root
    /// motion is baked into the pose (loop blend and keep original on orientation and position), as <see cref="BakeRoot"/> says.
    /// </summary>
    public sealed class HumanoidClipCurves
    {
        const double SlopeStep = 1e-5;

        /// <summary>Root orientation and position are baked into the pose: the avatar walks on the spot, as the mannequin does.</summary>
        public const bool BakeRoot = true;

        public LocomotionState Clip { get; }

        /// <summary>Stride positions of the keys (times are these times <see cref="GaitClipCurves.Length"/>).</summary>
        public List<double> Keys { get; }

        public List<HumanoidClipCurve> Curves { get; } = new List<HumanoidClipCurve>();

        public double Time(int key) => Keys[key] * GaitClipCurves.Length;

        HumanoidClipCurves(LocomotionState clip, List<double> keys)
        {
            Clip = clip;
            Keys = keys;
        }

        /// <summary>Every curve's name and its value in a pose, in the clips' order.</summary>
        public static List<(string Attribute, Func<BodyPose, double> Value)> Attributes()
        {
            var list = new List<(string, Func<BodyPose, double>)>
            {
                ("RootT.x", p => 0),
                ("RootT.y", p => p.HipHeight / Mannequin.StandingHipHeight),
                ("RootT.z", p => 0),
                ("RootQ.x", p => Math.Sin(p.PelvicTilt * Math.PI / 360)),
                ("RootQ.y", p => 0),
                ("RootQ.z", p => 0),
                ("RootQ.w", p => Math.Cos(p.PelvicTilt * Math.PI / 360)),
            };
            var names = HumanoidMuscles.Of(new BodyPose(default, default, 0, 0, 0, 0));
            for (int i = 0; i < names.Count; i++)
            {
                int index = i;
                list.Add((names[i].Name, p => HumanoidMuscles.Of(p)[index].Value));
            }
            return list;
        }

        public static HumanoidClipCurves Of(GaitClips clips, LocomotionState clip)
        {
            var keys = GaitClipCurves.KeyPositions(clips, clip);
            double length = GaitClipCurves.Length;
            var result = new HumanoidClipCurves(clip, keys);
            foreach (var (attribute, value) in Attributes())
            {
                var curve = new HumanoidClipCurve
                {
                    Attribute = attribute,
                    Values = new double[keys.Count],
                    InSlopes = new double[keys.Count],
                    OutSlopes = new double[keys.Count],
                };
                for (int k = 0; k < keys.Count; k++)
                {
                    double u = keys[k];
                    curve.Values[k] = value(GaitClipCurves.PoseAt(clips, clip, u));
                    if (clip == LocomotionState.Standing) continue;
                    double before = value(GaitClipCurves.PoseAt(clips, clip, Math.Max(0, u - SlopeStep)));
                    double after = value(GaitClipCurves.PoseAt(clips, clip, Math.Min(1, u + SlopeStep)));
                    curve.InSlopes[k] = u > 0 ? (curve.Values[k] - before) / (SlopeStep * length) : (after - curve.Values[k]) / (SlopeStep * length);
                    curve.OutSlopes[k] = u < 1 ? (after - curve.Values[k]) / (SlopeStep * length) : curve.InSlopes[k];
                }
                result.Curves.Add(curve);
            }
            return result;
        }
    }
}
