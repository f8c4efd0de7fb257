using System;
using System.Collections.Generic;
using System.Text;

namespace HeadGait.Tooling
{
    /// <summary>
    /// Writes one of <see cref="GaitClips"/> as a Humanoid AnimationClip: muscle curves (<see cref="HumanoidMuscles"/>) and
    /// the body's root curves RootT.x/y/z (body position, in the avatar's normalized human scale: standing = 1) and
    /// RootQ.x/y/z/w (body rotation: the pelvic tilt), all float curves on the Animator (classID 95) with an empty path,
    /// in m_FloatCurves and again in m_EditorCurves as Unity saves them. Same keys as the mannequin's clip.
    /// </summary>
    public static class HumanoidClipYaml
    {
        const double SlopeStep = 1e-5;

        public static List<(string Attribute, Func<BodyPose, double> Value)> Curves()
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

        public static string Write(GaitClips clips, LocomotionState clip)
        {
            var keys = GaitClipCurves.KeyPositions(clips, clip);
            double length = GaitClipCurves.Length;
            var curves = new StringBuilder();
            foreach (var (attribute, value) in Curves())
            {
                curves.Append("  - curve:\n      serializedVersion: 2\n      m_Curve:\n");
                var v = new double[keys.Count];
                var inSlope = new double[keys.Count];
                var outSlope = new double[keys.Count];
                bool constant = true;
                for (int k = 0; k < keys.Count; k++)
                {
                    double u = keys[k];
                    v[k] = value(GaitClipCurves.PoseAt(clips, clip, u));
                    if (clip != LocomotionState.Standing)
                    {
                        double before = value(GaitClipCurves.PoseAt(clips, clip, Math.Max(0, u - SlopeStep)));
                        double after = value(GaitClipCurves.PoseAt(clips, clip, Math.Min(1, u + SlopeStep)));
                        inSlope[k] = u > 0 ? (v[k] - before) / (SlopeStep * length) : (after - v[k]) / (SlopeStep * length);
                        outSlope[k] = u < 1 ? (after - v[k]) / (SlopeStep * length) : inSlope[k];
                    }
                    constant &= Math.Abs(v[k] - v[0]) < 1e-9 && inSlope[k] == 0 && outSlope[k] == 0;
                }
                for (int k = 0; k < keys.Count; k++)
                {
                    if (constant && k > 0 && k < keys.Count - 1) continue;
                    curves.Append("      - serializedVersion: 3\n        time: ").Append(UnityYaml.Number(keys[k] * length)).Append('\n');
                    curves.Append("        value: ").Append(UnityYaml.Number(v[k])).Append('\n');
                    curves.Append("        inSlope: ").Append(UnityYaml.Number(inSlope[k])).Append('\n');
                    curves.Append("        outSlope: ").Append(UnityYaml.Number(outSlope[k])).Append('\n');
                    curves.Append("        tangentMode: 0\n        weightedMode: 0\n        inWeight: 0.33333334\n        outWeight: 0.33333334\n");
                }
                curves.Append("      m_PreInfinity: 2\n      m_PostInfinity: 2\n      m_RotationOrder: 4\n");
                curves.Append("    attribute: ").Append(attribute).Append("\n    path: \n    classID: 95\n    script: {fileID: 0}\n");
            }

            var sb = new StringBuilder(UnityYaml.Header);
            UnityYaml.AppendClipHeader(sb, GaitClips.Name(clip));
            sb.Append("  m_EulerCurves: []\n  m_PositionCurves: []\n  m_ScaleCurves: []\n  m_FloatCurves:\n").Append(curves);
            sb.Append("  m_PPtrCurves: []\n  m_SampleRate: ").Append(GaitClipCurves.SampleRate).Append("\n  m_WrapMode: 0\n  m_Bounds:\n    m_Center: {x: 0, y: 0, z: 0}\n    m_Extent: {x: 0, y: 0, z: 0}\n");
            UnityYaml.AppendClipSettings(sb, length, GaitClipCurves.Loops(clip), bakeRoot: true);
            sb.Append("  m_EditorCurves:\n").Append(curves);
            sb.Append("  m_EulerEditorCurves: []\n  m_HasGenericRootTransform: 0\n  m_HasMotionFloatCurves: 0\n  m_Events: []\n");
            return sb.ToString();
        }
    }
}
