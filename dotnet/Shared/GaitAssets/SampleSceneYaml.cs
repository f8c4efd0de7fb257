using System.Text;

namespace HeadGait.Tooling
{
    /// <summary>
    /// The Legs sample's scene: a floor, a light, a camera looking at the avatar's legs from its right side, an instance of
    /// the drop-in prefab (its HeadImuSource switched to External, its FollowHead off) and a RecordingPlayer replaying a sample recording into
    /// the prefab's GaitLegAnimator, so the legs can be watched without a headset. A prefab instance is a PrefabInstance
    /// (1001) listing its modifications, plus a `stripped` document for each of its objects the scene refers to.
    /// It opens with the scene-settings documents Unity-written scenes have (<see cref="UnityYaml.SceneSettings"/>).
    /// </summary>
    public static class SampleSceneYaml
    {
        const string Scope = "Legs sample scene";

        public static long PrefabInstanceId => UnityYaml.StableFileId(Scope + ":instance");
        public static long StrippedLegAnimatorId => UnityYaml.StableFileId(Scope + ":instance/GaitLegAnimator");

        public static string Write(string package)
        {
            string legsGuid = GaitAssetFiles.LegsPrefabGuid;
            long legAnimatorInPrefab = UnityHierarchyYaml.Id(GaitAssetFiles.LegsRoot, "", "GaitLegAnimator");
            long imuInPrefab = UnityHierarchyYaml.Id(GaitAssetFiles.LegsRoot, "", "HeadImuSource");
            long followInPrefab = UnityHierarchyYaml.Id(GaitAssetFiles.LegsRoot, "", "FollowHead");
            long rootTransformInPrefab = UnityHierarchyYaml.Id(GaitAssetFiles.LegsRoot, "", "Transform");

            var h = new UnityHierarchyYaml(Scope);
            double[] V(double x, double y, double z) => new[] { x, y, z };
            // Tagged MainCamera as Unity's new scenes tag theirs: Camera.main (FollowHead's fallback head) finds it by the tag.
            h.Add("Main Camera", "Main Camera", V(3.2, 1.0, 0), V(5, -90, 0), tag: "MainCamera");
            h.AddComponent("Main Camera", 20, "Camera", "Camera",
                "  serializedVersion: 2\n  m_ClearFlags: 1\n  m_BackGroundColor: {r: 0.19, g: 0.3, b: 0.47, a: 0}\n  m_projectionMatrixMode: 1\n" +
                "  m_SensorSize: {x: 36, y: 24}\n  m_LensShift: {x: 0, y: 0}\n  m_FocalLength: 50\n  m_NormalizedViewPortRect:\n" +
                "    serializedVersion: 2\n    x: 0\n    y: 0\n    width: 1\n    height: 1\n  near clip plane: 0.1\n  far clip plane: 100\n" +
                "  field of view: 40\n  orthographic: 0\n  orthographic size: 5\n  m_Depth: -1\n  m_TargetDisplay: 0\n  m_TargetEye: 3\n" +
                "  m_HDR: 1\n  m_AllowMSAA: 1\n  m_AllowDynamicResolution: 0\n  m_ForceIntoRT: 0\n  m_OcclusionCulling: 1\n" +
                "  m_StereoConvergence: 10\n  m_StereoSeparation: 0.022\n", true);
            h.AddComponent("Main Camera", 81, "AudioListener", "AudioListener", "", true);
            h.Add("Directional Light", "Directional Light", V(0, 3, 0), V(50, -30, 0));
            h.AddComponent("Directional Light", 108, "Light", "Light",
                "  serializedVersion: 10\n  m_Type: 1\n  m_Shape: 0\n  m_Color: {r: 1, g: 0.96, b: 0.84, a: 1}\n  m_Intensity: 1\n  m_Range: 10\n" +
                "  m_SpotAngle: 30\n  m_Shadows:\n    m_Type: 2\n    m_Resolution: -1\n    m_Strength: 1\n    m_Bias: 0.05\n    m_NormalBias: 0.4\n" +
                "    m_NearPlane: 0.2\n", true);
            h.AddMesh("", "Floor", UnityHierarchyYaml.Plane, V(0, 0, 0), V(1, 1, 1), PrimitiveMaterials.Ground);
            h.Add("Recording Player", "Recording Player");
            h.AddScript("Recording Player", "RecordingPlayer", GaitAssetFiles.GuidOf(package, GaitAssetFiles.RecordingPlayerScript),
                "  target: " + UnityYaml.Ref(StrippedLegAnimatorId) + "\n  recording: " +
                UnityYaml.Ref(GaitAssetFiles.TextAssetId, GaitAssetFiles.GuidOf(package, GaitAssetFiles.SampleRecording), 3) + "\n  loop: 1\n  speed: 1\n");

            var sb = new StringBuilder(UnityYaml.Header);
            sb.Append(UnityYaml.SceneSettings);
            sb.Append(h.Write(withHeader: false));
            sb.Append(UnityYaml.Document(1001, PrefabInstanceId, "PrefabInstance"));
            sb.Append("  m_ObjectHideFlags: 0\n  serializedVersion: 2\n  m_Modification:\n    serializedVersion: 3\n    m_TransformParent: {fileID: 0}\n");
            sb.Append("    m_Modifications:\n");
            void Modify(long target, string property, string value)
            {
                sb.Append("    - target: ").Append(UnityYaml.Ref(target, legsGuid, 3)).Append('\n');
                sb.Append("      propertyPath: ").Append(property).Append("\n      value: ").Append(value).Append("\n      objectReference: {fileID: 0}\n");
            }
            Modify(rootTransformInPrefab, "m_LocalPosition.x", "0");
            Modify(rootTransformInPrefab, "m_LocalPosition.y", "0");
            Modify(rootTransformInPrefab, "m_LocalPosition.z", "0");
            Modify(imuInPrefab, "mode", ((int)2).ToString()); // HeadImuMode.External: the recording feeds the legs
            Modify(followInPrefab, "m_Enabled", "0"); // the avatar stays in front of this fixed camera, not under it
            sb.Append("    m_RemovedComponents: []\n    m_RemovedGameObjects: []\n    m_AddedGameObjects: []\n    m_AddedComponents: []\n");
            sb.Append("  m_SourcePrefab: ").Append(UnityYaml.Ref(GaitAssetFiles.PrefabRootId, legsGuid, 3)).Append('\n');
            sb.Append(UnityYaml.Document(114, StrippedLegAnimatorId, "MonoBehaviour", stripped: true));
            sb.Append("  m_CorrespondingSourceObject: ").Append(UnityYaml.Ref(legAnimatorInPrefab, legsGuid, 3)).Append('\n');
            sb.Append("  m_PrefabInstance: ").Append(UnityYaml.Ref(PrefabInstanceId)).Append("\n  m_PrefabAsset: {fileID: 0}\n");
            sb.Append("  m_GameObject: {fileID: 0}\n  m_Enabled: 1\n  m_EditorHideFlags: 0\n");
            sb.Append("  m_Script: ").Append(UnityYaml.Ref(11500000, GaitAssetFiles.GuidOf(package, GaitAssetFiles.GaitLegAnimatorScript), 3)).Append('\n');
            sb.Append("  m_Name: \n  m_EditorClassIdentifier: \n");
            return sb.ToString();
        }
    }
}
