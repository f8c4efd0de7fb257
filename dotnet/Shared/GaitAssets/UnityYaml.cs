using System;
using System.Globalization;
using System.Text;

namespace HeadGait.Tooling
{
    /// <summary>
    /// Pieces of Unity's text serialization (force-text YAML). Each object is a document headed `--- !u!CLASS &amp;FILEID`;
    /// class IDs from https://docs.unity3d.com/Manual/ClassIDReference.html (1 GameObject, 4 Transform, 23 MeshRenderer,
    /// 33 MeshFilter, 74 AnimationClip, 91 AnimatorController, 95 Animator, 114 MonoBehaviour, 1001 PrefabInstance,
    /// 1101 AnimatorStateTransition, 1102 AnimatorState, 1107 AnimatorStateMachine). References are {fileID, guid, type}:
    /// type 2 an asset in a native file, type 3 an object in an imported file (script, text, prefab).
    /// </summary>
    public static class UnityYaml
    {
        public const string Header = "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n";

        /// <summary>Unity's built-in resources: primitive meshes (Cube 10202, Cylinder 10206, Sphere 10207, Capsule 10208).</summary>
        public const string BuiltinExtraGuid = "0000000000000000e000000000000000";
        /// <summary>Unity's built-in extra resources: Default-Material (10303, magenta in URP: not used), Default-Skybox (10304).</summary>
        public const string BuiltinMaterialGuid = "0000000000000000f000000000000000";

        /// <summary>
        /// The four scene-settings documents every Unity-written scene opens with (OcclusionCullingSettings 29, RenderSettings
        /// 104, LightmapSettings 157, NavMeshSettings 196), at the serialized versions Unity 6 writes (Manual: "Example of a
        /// YAML scene file"); fields left out take Unity's defaults. Ambient from the default skybox, which is a built-in
        /// Skybox/Procedural material that URP draws too; no baked lighting.
        /// </summary>
        public const string SceneSettings =
            "--- !u!29 &1\nOcclusionCullingSettings:\n  m_ObjectHideFlags: 0\n  serializedVersion: 2\n  m_OcclusionBakeSettings:\n" +
            "    smallestOccluder: 5\n    smallestHole: 0.25\n    backfaceThreshold: 100\n  m_SceneGUID: 00000000000000000000000000000000\n" +
            "  m_OcclusionCullingData: {fileID: 0}\n" +
            "--- !u!104 &2\nRenderSettings:\n  m_ObjectHideFlags: 0\n  serializedVersion: 10\n  m_Fog: 0\n" +
            "  m_AmbientSkyColor: {r: 0.212, g: 0.227, b: 0.259, a: 1}\n  m_AmbientEquatorColor: {r: 0.114, g: 0.125, b: 0.133, a: 1}\n" +
            "  m_AmbientGroundColor: {r: 0.047, g: 0.043, b: 0.035, a: 1}\n  m_AmbientIntensity: 1\n  m_AmbientMode: 0\n" +
            "  m_SkyboxMaterial: {fileID: 10304, guid: " + BuiltinMaterialGuid + ", type: 0}\n  m_Sun: {fileID: 0}\n" +
            "--- !u!157 &3\nLightmapSettings:\n  m_ObjectHideFlags: 0\n  serializedVersion: 13\n  m_BakeOnSceneLoad: 0\n  m_GISettings:\n" +
            "    serializedVersion: 2\n    m_BounceScale: 1\n    m_IndirectOutputScale: 1\n    m_AlbedoBoost: 1\n    m_EnvironmentLightingMode: 0\n" +
            "    m_EnableBakedLightmaps: 0\n    m_EnableRealtimeLightmaps: 0\n  m_LightingDataAsset: {fileID: 0}\n  m_LightingSettings: {fileID: 0}\n" +
            "--- !u!196 &4\nNavMeshSettings:\n  serializedVersion: 2\n  m_ObjectHideFlags: 0\n  m_BuildSettings:\n    serializedVersion: 3\n" +
            "    agentTypeID: 0\n    agentRadius: 0.5\n    agentHeight: 2\n    agentSlope: 45\n    agentClimb: 0.4\n  m_NavMeshData: {fileID: 0}\n";

        public static string Document(int classId, long fileId, string type, bool stripped = false)
            => $"--- !u!{classId} &{fileId}{(stripped ? " stripped" : "")}\n{type}:\n";

        /// <summary>An AnimationClip document's opening lines (class 74), up to its curves.</summary>
        public static void AppendClipHeader(System.Text.StringBuilder sb, string name)
        {
            sb.Append(Document(74, 7400000, "AnimationClip"));
            sb.Append("  m_ObjectHideFlags: 0\n  m_CorrespondingSourceObject: {fileID: 0}\n  m_PrefabInstance: {fileID: 0}\n  m_PrefabAsset: {fileID: 0}\n");
            sb.Append("  m_Name: ").Append(name).Append('\n');
            sb.Append("  serializedVersion: 7\n  m_Legacy: 0\n  m_Compressed: 0\n  m_UseHighQualityCurve: 1\n  m_RotationCurves: []\n  m_CompressedRotationCurves: []\n");
        }

        /// <summary>
        /// An AnimationClip's binding constant (rebuilt by the editor from the curves on import) and settings; with
        /// <paramref name="bakeRoot"/> root rotation and position are baked into the pose (the avatar stays where it is put).
        /// </summary>
        public static void AppendClipSettings(System.Text.StringBuilder sb, double length, bool loop, bool bakeRoot)
        {
            sb.Append("  m_ClipBindingConstant:\n    genericBindings: []\n    pptrCurveMapping: []\n");
            sb.Append("  m_AnimationClipSettings:\n    serializedVersion: 2\n    m_AdditiveReferencePoseClip: {fileID: 0}\n    m_AdditiveReferencePoseTime: 0\n");
            sb.Append("    m_StartTime: 0\n    m_StopTime: ").Append(Number(length)).Append('\n');
            sb.Append("    m_OrientationOffsetY: 0\n    m_Level: 0\n    m_CycleOffset: 0\n    m_HasAdditiveReferencePose: 0\n");
            sb.Append("    m_LoopTime: ").Append(loop ? 1 : 0).Append('\n');
            int b = bakeRoot ? 1 : 0;
            sb.Append("    m_LoopBlend: 0\n    m_LoopBlendOrientation: ").Append(b).Append("\n    m_LoopBlendPositionY: ").Append(b).Append("\n    m_LoopBlendPositionXZ: ").Append(b).Append('\n');
            sb.Append("    m_KeepOriginalOrientation: ").Append(b).Append("\n    m_KeepOriginalPositionY: 1\n    m_KeepOriginalPositionXZ: ").Append(b).Append("\n    m_HeightFromFeet: 0\n    m_Mirror: 0\n");
        }

        public static string Ref(long fileId) => $"{{fileID: {fileId}}}";

        public static string Ref(long fileId, string guid, int type) => $"{{fileID: {fileId}, guid: {guid}, type: {type}}}";

        public static string Number(double x)
        {
            if (Math.Abs(x) < 1e-9) return "0";
            return x.ToString("0.#######", CultureInfo.InvariantCulture);
        }

        public static string Vector(double x, double y, double z) => $"{{x: {Number(x)}, y: {Number(y)}, z: {Number(z)}}}";

        /// <summary>
        /// A stable local fileID for an object named by a key (a path in the hierarchy and a component), so regenerating a
        /// prefab keeps the IDs that scenes and prefab instances refer to. FNV-1a, kept positive and away from small IDs.
        /// </summary>
        public static long StableFileId(string key)
        {
            ulong h = 14695981039346656037UL;
            foreach (byte b in Encoding.UTF8.GetBytes(key))
            {
                h ^= b;
                h *= 1099511628211UL;
            }
            return (long)(h % 9000000000000000000UL) + 100000000000L;
        }
    }
}
