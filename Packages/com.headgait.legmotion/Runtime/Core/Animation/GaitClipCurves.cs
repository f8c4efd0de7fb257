using System;
using System.Collections.Generic;

namespace HeadGait
{
    /// <summary>
    /// One animated transform property of a gait clip: its keys' values and one-sided slopes (per second of clip time) for
    /// the x, y and z components. <see cref="Property"/> is Unity's binding name on the Transform: "m_LocalPosition" or
    /// "localEulerAnglesRaw" (Euler angles in degrees, interpolated as Euler, as the Animation window keys them), each
    /// component a float curve named Property + ".x" etc.
    /// </summary>
    public sealed class GaitClipChannel
    {
        public string Path;
        public bool IsPosition;
        /// <summary>[key][component]</summary>
        public double[][] Values, InSlopes, OutSlopes;

        public string Property => IsPosition ? "m_LocalPosition" : "localEulerAnglesRaw";

        /// <summary>The float curve of one component (0 x, 1 y, 2 z): "m_LocalPosition.y", "localEulerAnglesRaw.x", ...</summary>
        public string Attribute(int component) => Property + "." + "xyz"[component];

        /// <summary>A component that never changes needs only its first and last key.</summary>
        public bool IsConstant(int component)
        {
            for (int k = 0; k < Values.Length; k++)
                if (Values[k][component] != Values[0][component] || InSlopes[k][component] != 0 || OutSlopes[k][component] != 0) return false;
            return true;
        }
    }

    /// <summary>
    /// The keyed curves of one of <see cref="GaitClips"/> on the mannequin's hierarchy (paths from <see cref="Mannequin"/>):
    /// one place for what `headgait clips` writes as .anim YAML and what Tools > HeadGait > Create Gait Clips sets with
    /// AnimationUtility.SetEditorCurve. Sagittal rotations are about the local x axis (Unity: +x pitches forward down, so
    /// flexion is negative x). The clip lasts one stride at the default step period; its normalized time is the stride position.
    /// </summary>
    public sealed class GaitClipCurves
    {
        /// <summary>Clip length, seconds: one stride at <see cref="AnimatorSettings.DefaultStepPeriod"/>.</summary>
        public static double Length => 2 * new AnimatorSettings().DefaultStepPeriod;

        /// <summary>Frames per second the clip is shown with in the Animation window.</summary>
        public const int SampleRate = 60;

        /// <summary>Uniform keys per stride, besides the keys at each contact and toe-off.</summary>
        public const int UniformKeys = 40;

        /// <summary>Keys just before an event hold the value on its near side, so a step in the hips' height stays a step.</summary>
        public const double BeforeEvent = 1e-4;

        const double SlopeStep = 1e-5;

        /// <summary>Walking and Standing loop; start and finish clips play once.</summary>
        public static bool Loops(LocomotionState clip) => clip == LocomotionState.Walking || clip == LocomotionState.Standing;

        public LocomotionState Clip { get; }

        /// <summary>Stride positions of the keys (times are these times <see cref="Length"/>).</summary>
        public List<double> Keys { get; }

        public List<GaitClipChannel> Channels { get; } = new List<GaitClipChannel>();

        public double Time(int key) => Keys[key] * Length;

        GaitClipCurves(LocomotionState clip, List<double> keys)
        {
            Clip = clip;
            Keys = keys;
        }

        static List<(string Path, bool IsPosition, Func<BodyPose, double[]> Value)> ChannelValues()
        {
            var list = new List<(string, bool, Func<BodyPose, double[]>)>
            {
                (Mannequin.Hips, true, p => new[] { 0.0, p.HipHeight, 0.0 }),
                (Mannequin.Hips, false, p => new[] { p.PelvicTilt, 0.0, 0.0 }),
            };
            foreach (Foot foot in new[] { Foot.Left, Foot.Right })
            {
                Foot f = foot;
                list.Add((Mannequin.UpperLeg(f), false, p => new[] { -p.Of(f).Hip, 0.0, 0.0 }));
                list.Add((Mannequin.LowerLeg(f), false, p => new[] { p.Of(f).Knee, 0.0, 0.0 }));
                list.Add((Mannequin.FootPath(f), false, p => new[] { -p.Of(f).Ankle, 0.0, 0.0 }));
                list.Add((Mannequin.Toes(f), false, p => new[] { -p.Leg(f).ToeBend, 0.0, 0.0 }));
                list.Add((Mannequin.UpperArm(f), false, p => new[] { -(f == Foot.Left ? p.LeftArm : p.RightArm), 0.0, 0.0 }));
            }
            return list;
        }

        /// <summary>Stride positions that carry a key: a uniform grid, each contact and toe-off, and a key just before each.</summary>
        public static List<double> KeyPositions(GaitClips clips, LocomotionState clip)
        {
            var keys = new SortedSet<double>();
            if (clip == LocomotionState.Standing)
            {
                keys.Add(0);
                keys.Add(1);
                return new List<double>(keys);
            }
            for (int i = 0; i <= UniformKeys; i++) keys.Add((double)i / UniformKeys);
            foreach (Foot foot in new[] { Foot.Left, Foot.Right })
            {
                foreach (double e in new[] { clips.InitialContact(foot), clips.ToeOff(foot) })
                {
                    double at = e == 0 ? 1 : e;
                    keys.Add(e);
                    keys.Add(at - BeforeEvent);
                }
            }
            // Grid keys too close to an event key would only add noise.
            var list = new List<double>();
            foreach (double k in keys)
                if (list.Count == 0 || k - list[list.Count - 1] > BeforeEvent / 2) list.Add(k);
            return list;
        }

        /// <summary>The clip's pose at a key: 1.0 is the end of the stride, approached from below.</summary>
        public static BodyPose PoseAt(GaitClips clips, LocomotionState clip, double u) => clips.Pose(clip, u >= 1 ? 1 - 1e-12 : u);

        /// <summary>Every channel's values and slopes at every key of the clip.</summary>
        public static GaitClipCurves Of(GaitClips clips, LocomotionState clip)
        {
            var curves = new GaitClipCurves(clip, KeyPositions(clips, clip));
            var keys = curves.Keys;
            double length = Length;
            foreach (var (path, isPosition, value) in ChannelValues())
            {
                var channel = new GaitClipChannel
                {
                    Path = path,
                    IsPosition = isPosition,
                    Values = new double[keys.Count][],
                    InSlopes = new double[keys.Count][],
                    OutSlopes = new double[keys.Count][],
                };
                for (int k = 0; k < keys.Count; k++)
                {
                    double u = keys[k];
                    var v = value(PoseAt(clips, clip, u));
                    var before = value(PoseAt(clips, clip, Math.Max(0, u - SlopeStep)));
                    var after = value(PoseAt(clips, clip, Math.Min(1, u + SlopeStep)));
                    channel.Values[k] = v;
                    channel.InSlopes[k] = new double[3];
                    channel.OutSlopes[k] = new double[3];
                    for (int j = 0; j < 3; j++)
                    {
                        if (clip == LocomotionState.Standing) continue;
                        channel.InSlopes[k][j] = u > 0 ? (v[j] - before[j]) / (SlopeStep * length) : (after[j] - v[j]) / (SlopeStep * length);
                        channel.OutSlopes[k][j] = u < 1 ? (after[j] - v[j]) / (SlopeStep * length) : channel.InSlopes[k][j];
                    }
                }
                curves.Channels.Add(channel);
            }
            return curves;
        }
    }
}
