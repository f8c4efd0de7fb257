using System;
using System.Collections.Generic;
using System.Text;

namespace HeadGait.Tooling
{
    /// <summary>
    /// Writes one of <see cref="GaitClips"/> as a Unity AnimationClip (.anim, class 74) of transform curves on the
    /// mannequin's hierarchy (paths from <see cref="Mannequin"/>): runtime curves (m_PositionCurves, m_EulerCurves, keys of
    /// Vector3) and the per-component editor curves (m_EditorCurves: m_LocalPosition.x, localEulerAnglesRaw.x, ... on class 4
    /// Transform) that Unity's Animation window edits and rebuilds the runtime clip from. Field layout follows clips saved by
    /// Unity 2019-2022 in public projects (e.g. an AnimationClip writer found by searching 'localEulerAnglesRaw.x'); sagittal
    /// rotations are about the local x axis (Unity: +x pitches forward down, so flexion is negative x).
    /// The clip lasts one stride at the default step period; its normalized time is the stride position.
    /// </summary>
    public static class GaitClipYaml
    {
        /// <summary>Clip length, seconds: one stride at <see cref="AnimatorSettings.DefaultStepPeriod"/>.</summary>
        public static double Length => 2 * new AnimatorSettings().DefaultStepPeriod;

        /// <summary>Uniform keys per stride, besides the keys at each contact and toe-off.</summary>
        public const int UniformKeys = 40;

        /// <summary>Keys just before an event hold the value on its near side, so a step in the hips' height stays a step.</summary>
        public const double BeforeEvent = 1e-4;

        const double SlopeStep = 1e-5;

        enum Kind { Position, Euler }

        sealed class Channel
        {
            public string Path;
            public Kind Kind;
            public Func<BodyPose, double[]> Value;
        }

        static List<Channel> Channels()
        {
            var list = new List<Channel>
            {
                new Channel { Path = Mannequin.Hips, Kind = Kind.Position, Value = p => new[] { 0.0, p.HipHeight, 0.0 } },
                new Channel { Path = Mannequin.Hips, Kind = Kind.Euler, Value = p => new[] { p.PelvicTilt, 0.0, 0.0 } },
            };
            foreach (Foot foot in new[] { Foot.Left, Foot.Right })
            {
                Foot f = foot;
                list.Add(new Channel { Path = Mannequin.UpperLeg(f), Kind = Kind.Euler, Value = p => new[] { -p.Of(f).Hip, 0.0, 0.0 } });
                list.Add(new Channel { Path = Mannequin.LowerLeg(f), Kind = Kind.Euler, Value = p => new[] { p.Of(f).Knee, 0.0, 0.0 } });
                list.Add(new Channel { Path = Mannequin.FootPath(f), Kind = Kind.Euler, Value = p => new[] { -p.Of(f).Ankle, 0.0, 0.0 } });
                list.Add(new Channel { Path = Mannequin.Toes(f), Kind = Kind.Euler, Value = p => new[] { -p.Leg(f).ToeBend, 0.0, 0.0 } });
                list.Add(new Channel { Path = Mannequin.UpperArm(f), Kind = Kind.Euler, Value = p => new[] { -(f == Foot.Left ? p.LeftArm : p.RightArm), 0.0, 0.0 } });
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

        public static string Write(GaitClips clips, LocomotionState clip)
        {
            var keys = KeyPositions(clips, clip);
            var channels = Channels();
            double length = Length;
            // Values and one-sided slopes (per second of clip time) of every channel at every key.
            var values = new double[channels.Count][][];
            var inSlopes = new double[channels.Count][][];
            var outSlopes = new double[channels.Count][][];
            for (int c = 0; c < channels.Count; c++)
            {
                values[c] = new double[keys.Count][];
                inSlopes[c] = new double[keys.Count][];
                outSlopes[c] = new double[keys.Count][];
                for (int k = 0; k < keys.Count; k++)
                {
                    double u = keys[k];
                    var v = channels[c].Value(PoseAt(clips, clip, u));
                    var before = channels[c].Value(PoseAt(clips, clip, Math.Max(0, u - SlopeStep)));
                    var after = channels[c].Value(PoseAt(clips, clip, Math.Min(1, u + SlopeStep)));
                    values[c][k] = v;
                    inSlopes[c][k] = new double[3];
                    outSlopes[c][k] = new double[3];
                    for (int j = 0; j < 3; j++)
                    {
                        if (clip == LocomotionState.Standing) continue;
                        inSlopes[c][k][j] = u > 0 ? (v[j] - before[j]) / (SlopeStep * length) : (after[j] - v[j]) / (SlopeStep * length);
                        outSlopes[c][k][j] = u < 1 ? (after[j] - v[j]) / (SlopeStep * length) : inSlopes[c][k][j];
                    }
                }
            }

            var sb = new StringBuilder(UnityYaml.Header);
            UnityYaml.AppendClipHeader(sb, GaitClips.Name(clip));
            VectorCurves(sb, "m_EulerCurves", Kind.Euler, channels, keys, values, inSlopes, outSlopes, length);
            VectorCurves(sb, "m_PositionCurves", Kind.Position, channels, keys, values, inSlopes, outSlopes, length);
            sb.Append("  m_ScaleCurves: []\n  m_FloatCurves: []\n  m_PPtrCurves: []\n  m_SampleRate: 60\n  m_WrapMode: 0\n");
            sb.Append("  m_Bounds:\n    m_Center: {x: 0, y: 0, z: 0}\n    m_Extent: {x: 0, y: 0, z: 0}\n");
            UnityYaml.AppendClipSettings(sb, length, clip == LocomotionState.Walking || clip == LocomotionState.Standing, bakeRoot: false);
            sb.Append("  m_EditorCurves:\n");
            string[] axes = { "x", "y", "z" };
            for (int c = 0; c < channels.Count; c++)
            {
                string attribute = channels[c].Kind == Kind.Position ? "m_LocalPosition." : "localEulerAnglesRaw.";
                for (int j = 0; j < 3; j++)
                {
                    sb.Append("  - curve:\n      serializedVersion: 2\n      m_Curve:\n");
                    bool constant = true;
                    for (int k = 0; k < keys.Count; k++)
                        constant &= values[c][k][j] == values[c][0][j] && inSlopes[c][k][j] == 0 && outSlopes[c][k][j] == 0;
                    for (int k = 0; k < keys.Count; k++)
                    {
                        if (constant && k > 0 && k < keys.Count - 1) continue; // a constant needs its ends only
                        sb.Append("      - serializedVersion: 3\n        time: ").Append(UnityYaml.Number(keys[k] * length)).Append('\n');
                        sb.Append("        value: ").Append(UnityYaml.Number(values[c][k][j])).Append('\n');
                        sb.Append("        inSlope: ").Append(UnityYaml.Number(inSlopes[c][k][j])).Append('\n');
                        sb.Append("        outSlope: ").Append(UnityYaml.Number(outSlopes[c][k][j])).Append('\n');
                        sb.Append("        tangentMode: 0\n        weightedMode: 0\n        inWeight: 0.33333334\n        outWeight: 0.33333334\n");
                    }
                    sb.Append("      m_PreInfinity: 2\n      m_PostInfinity: 2\n      m_RotationOrder: 4\n");
                    sb.Append("    attribute: ").Append(attribute).Append(axes[j]).Append('\n');
                    sb.Append("    path: ").Append(channels[c].Path).Append('\n');
                    sb.Append("    classID: 4\n    script: {fileID: 0}\n");
                }
            }
            sb.Append("  m_EulerEditorCurves: []\n  m_HasGenericRootTransform: 0\n  m_HasMotionFloatCurves: 0\n  m_Events: []\n");
            return sb.ToString();
        }

        static void VectorCurves(StringBuilder sb, string field, Kind kind, List<Channel> channels, List<double> keys,
                                 double[][][] values, double[][][] inSlopes, double[][][] outSlopes, double length)
        {
            sb.Append("  ").Append(field).Append(":\n");
            for (int c = 0; c < channels.Count; c++)
            {
                if (channels[c].Kind != kind) continue;
                sb.Append("  - curve:\n      serializedVersion: 2\n      m_Curve:\n");
                for (int k = 0; k < keys.Count; k++)
                {
                    var v = values[c][k];
                    var i = inSlopes[c][k];
                    var o = outSlopes[c][k];
                    sb.Append("      - serializedVersion: 3\n        time: ").Append(UnityYaml.Number(keys[k] * length)).Append('\n');
                    sb.Append("        value: ").Append(UnityYaml.Vector(v[0], v[1], v[2])).Append('\n');
                    sb.Append("        inSlope: ").Append(UnityYaml.Vector(i[0], i[1], i[2])).Append('\n');
                    sb.Append("        outSlope: ").Append(UnityYaml.Vector(o[0], o[1], o[2])).Append('\n');
                    sb.Append("        tangentMode: 0\n        weightedMode: 0\n");
                    sb.Append("        inWeight: {x: 0.33333334, y: 0.33333334, z: 0.33333334}\n        outWeight: {x: 0.33333334, y: 0.33333334, z: 0.33333334}\n");
                }
                sb.Append("      m_PreInfinity: 2\n      m_PostInfinity: 2\n      m_RotationOrder: 4\n");
                sb.Append("    path: ").Append(channels[c].Path).Append('\n');
            }
        }
    }
}
