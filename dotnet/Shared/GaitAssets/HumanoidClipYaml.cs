using System.Text;

namespace HeadGait.Tooling
{
    /// <summary>
    /// Writes one of <see cref="GaitClips"/> as a Humanoid AnimationClip from <see cref="HumanoidClipCurves"/>: float curves
    /// on the Animator (classID 95) with an empty path, in m_FloatCurves and again in m_EditorCurves as Unity saves them.
    /// </summary>
    public static class HumanoidClipYaml
    {
        public static string Write(GaitClips clips, LocomotionState clip)
        {
            var of = HumanoidClipCurves.Of(clips, clip);
            var curves = new StringBuilder();
            foreach (var c in of.Curves)
            {
                curves.Append("  - curve:\n      serializedVersion: 2\n      m_Curve:\n");
                bool constant = c.IsConstant;
                for (int k = 0; k < of.Keys.Count; k++)
                {
                    if (constant && k > 0 && k < of.Keys.Count - 1) continue;
                    curves.Append("      - serializedVersion: 3\n        time: ").Append(UnityYaml.Number(of.Time(k))).Append('\n');
                    curves.Append("        value: ").Append(UnityYaml.Number(c.Values[k])).Append('\n');
                    curves.Append("        inSlope: ").Append(UnityYaml.Number(c.InSlopes[k])).Append('\n');
                    curves.Append("        outSlope: ").Append(UnityYaml.Number(c.OutSlopes[k])).Append('\n');
                    curves.Append("        tangentMode: 0\n        weightedMode: 0\n        inWeight: 0.33333334\n        outWeight: 0.33333334\n");
                }
                curves.Append("      m_PreInfinity: 2\n      m_PostInfinity: 2\n      m_RotationOrder: 4\n");
                curves.Append("    attribute: ").Append(c.Attribute).Append("\n    path: \n    classID: 95\n    script: {fileID: 0}\n");
            }

            var sb = new StringBuilder(UnityYaml.Header);
            UnityYaml.AppendClipHeader(sb, GaitClips.Name(clip));
            sb.Append("  m_EulerCurves: []\n  m_PositionCurves: []\n  m_ScaleCurves: []\n  m_FloatCurves:\n").Append(curves);
            sb.Append("  m_PPtrCurves: []\n  m_SampleRate: ").Append(GaitClipCurves.SampleRate).Append("\n  m_WrapMode: 0\n  m_Bounds:\n    m_Center: {x: 0, y: 0, z: 0}\n    m_Extent: {x: 0, y: 0, z: 0}\n");
            UnityYaml.AppendClipSettings(sb, GaitClipCurves.Length, GaitClipCurves.Loops(clip), bakeRoot: HumanoidClipCurves.BakeRoot);
            sb.Append("  m_EditorCurves:\n").Append(curves);
            sb.Append("  m_EulerEditorCurves: []\n  m_HasGenericRootTransform: 0\n  m_HasMotionFloatCurves: 0\n  m_Events: []\n");
            return sb.ToString();
        }
    }
}
