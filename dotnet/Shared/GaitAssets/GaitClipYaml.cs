using System.Text;

namespace HeadGait.Tooling
{
    /// <summary>
    /// Writes one of <see cref="GaitClips"/> as a Unity AnimationClip (.anim, class 74) from <see cref="GaitClipCurves"/> (the
    /// editor's Create Gait Clips sets the same curves): runtime curves (m_PositionCurves, m_EulerCurves, keys of Vector3)
    /// and the per-component editor curves (m_EditorCurves: m_LocalPosition.x, localEulerAnglesRaw.x, ... on class 4
    /// Transform) that Unity's Animation window edits and rebuilds the runtime clip from. Field layout follows clips saved in
    /// public projects (e.g. an AnimationClip writer found by searching 'localEulerAnglesRaw.x'), at the AnimationClip
    /// serializedVersion 7 that 2022.3 and Unity 6 write (2021.3 writes 6: the package needs Unity 6 for its other assets,
    /// PackageMinimumEditorTests).
    /// </summary>
    public static class GaitClipYaml
    {
        public static string Write(GaitClips clips, LocomotionState clip)
        {
            var curves = GaitClipCurves.Of(clips, clip);
            var sb = new StringBuilder(UnityYaml.Header);
            UnityYaml.AppendClipHeader(sb, GaitClips.Name(clip));
            VectorCurves(sb, "m_EulerCurves", false, curves);
            VectorCurves(sb, "m_PositionCurves", true, curves);
            sb.Append("  m_ScaleCurves: []\n  m_FloatCurves: []\n  m_PPtrCurves: []\n  m_SampleRate: ").Append(GaitClipCurves.SampleRate).Append("\n  m_WrapMode: 0\n");
            sb.Append("  m_Bounds:\n    m_Center: {x: 0, y: 0, z: 0}\n    m_Extent: {x: 0, y: 0, z: 0}\n");
            UnityYaml.AppendClipSettings(sb, GaitClipCurves.Length, GaitClipCurves.Loops(clip), bakeRoot: false);
            sb.Append("  m_EditorCurves:\n");
            foreach (var channel in curves.Channels)
            {
                for (int j = 0; j < 3; j++)
                {
                    sb.Append("  - curve:\n      serializedVersion: 2\n      m_Curve:\n");
                    bool constant = channel.IsConstant(j);
                    for (int k = 0; k < curves.Keys.Count; k++)
                    {
                        if (constant && k > 0 && k < curves.Keys.Count - 1) continue; // a constant needs its ends only
                        sb.Append("      - serializedVersion: 3\n        time: ").Append(UnityYaml.Number(curves.Time(k))).Append('\n');
                        sb.Append("        value: ").Append(UnityYaml.Number(channel.Values[k][j])).Append('\n');
                        sb.Append("        inSlope: ").Append(UnityYaml.Number(channel.InSlopes[k][j])).Append('\n');
                        sb.Append("        outSlope: ").Append(UnityYaml.Number(channel.OutSlopes[k][j])).Append('\n');
                        sb.Append("        tangentMode: 0\n        weightedMode: 0\n        inWeight: 0.33333334\n        outWeight: 0.33333334\n");
                    }
                    sb.Append("      m_PreInfinity: 2\n      m_PostInfinity: 2\n      m_RotationOrder: 4\n");
                    sb.Append("    attribute: ").Append(channel.Attribute(j)).Append('\n');
                    sb.Append("    path: ").Append(channel.Path).Append('\n');
                    sb.Append("    classID: 4\n    script: {fileID: 0}\n");
                }
            }
            sb.Append("  m_EulerEditorCurves: []\n  m_HasGenericRootTransform: 0\n  m_HasMotionFloatCurves: 0\n  m_Events: []\n");
            return sb.ToString();
        }

        static void VectorCurves(StringBuilder sb, string field, bool positions, GaitClipCurves curves)
        {
            sb.Append("  ").Append(field).Append(":\n");
            foreach (var channel in curves.Channels)
            {
                if (channel.IsPosition != positions) continue;
                sb.Append("  - curve:\n      serializedVersion: 2\n      m_Curve:\n");
                for (int k = 0; k < curves.Keys.Count; k++)
                {
                    var v = channel.Values[k];
                    var i = channel.InSlopes[k];
                    var o = channel.OutSlopes[k];
                    sb.Append("      - serializedVersion: 3\n        time: ").Append(UnityYaml.Number(curves.Time(k))).Append('\n');
                    sb.Append("        value: ").Append(UnityYaml.Vector(v[0], v[1], v[2])).Append('\n');
                    sb.Append("        inSlope: ").Append(UnityYaml.Vector(i[0], i[1], i[2])).Append('\n');
                    sb.Append("        outSlope: ").Append(UnityYaml.Vector(o[0], o[1], o[2])).Append('\n');
                    sb.Append("        tangentMode: 0\n        weightedMode: 0\n");
                    sb.Append("        inWeight: {x: 0.33333334, y: 0.33333334, z: 0.33333334}\n        outWeight: {x: 0.33333334, y: 0.33333334, z: 0.33333334}\n");
                }
                sb.Append("      m_PreInfinity: 2\n      m_PostInfinity: 2\n      m_RotationOrder: 4\n");
                sb.Append("    path: ").Append(channel.Path).Append('\n');
            }
        }
    }
}
