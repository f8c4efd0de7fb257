using System;
using System.Collections.Generic;
using System.IO;
using System.Text;

namespace HeadGait.Tooling
{
    /// <summary>
    /// The Unity assets generated from the core (clips, controller, mannequin, drop-in prefab, sample scene): where they
    /// live in the package, their fixed GUIDs, and writing them all. Scripts and the COR template are referred to by the
    /// GUIDs in their existing .meta files.
    /// </summary>
    public static class GaitAssetFiles
    {
        public const string AnimationFolder = "Runtime/Animation";
        public const string PrefabFolder = "Runtime/Prefabs";
        public const string SampleFolder = "Samples~/Legs";
        public const string Controller = AnimationFolder + "/HeadGait Legs.controller";
        public const string ControllerGuid = "d924acd389af410a82b9ab5fba8d479c";
        public const string LegsPrefab = PrefabFolder + "/HeadGait Legs.prefab";
        public const string LegsPrefabGuid = "6701221dbb664f63a3a3c62cc8e95a65";
        public const string MannequinPrefab = PrefabFolder + "/HeadGait Mannequin.prefab";
        public const string MannequinPrefabGuid = "d037fc77ae304cf6832af7a3aeb7ff1c";
        public const string SampleScene = SampleFolder + "/HeadGait Legs Sample.unity";
        /// <summary>The recording the sample scene plays (from the "Sample recordings" sample, which must be imported too).</summary>
        public const string SampleRecording = "Samples~/Recordings/eval/start_stop.csv";
        public const string GaitLegAnimatorScript = "Runtime/Components/GaitLegAnimator.cs";
        public const string HeadImuSourceScript = "Runtime/Components/HeadImuSource.cs";
        public const string RecordingPlayerScript = "Runtime/Components/RecordingPlayer.cs";
        public const string FollowHeadScript = "Runtime/Components/FollowHead.cs";
        public const string CorTemplate = "Models/cor_template.txt";

        /// <summary>A TextAsset's fileID in its imported file (class 49).</summary>
        public const long TextAssetId = 4900000;
        /// <summary>A prefab's root as a prefab instance's source (class 1001 * 100000).</summary>
        public const long PrefabRootId = 100100000;

        public const string LegsRoot = Mannequin.LegsPrefabRoot;
        public const string MannequinRoot = Mannequin.PrefabRoot;
        /// <summary>The mannequin's path under the drop-in prefab's root.</summary>
        public const string AvatarName = Mannequin.LegsAvatar;

        public static string ClipPath(LocomotionState clip) => AnimationFolder + "/" + GaitClips.Name(clip) + ".anim";

        /// <summary>The Humanoid (muscle) version of a clip, for the developer's own avatar.</summary>
        public static string HumanoidClipPath(LocomotionState clip) => AnimationFolder + "/Humanoid/" + GaitClips.Name(clip) + ".anim";

        /// <summary>The controller with every clip replaced by its Humanoid version.</summary>
        public const string HumanoidController = AnimationFolder + "/HeadGait Legs Humanoid.overrideController";

        /// <summary>Writes every generated asset under the package folder; returns the paths written (relative).</summary>
        public static List<string> WriteAll(string package, PhaseMap map)
        {
            var written = new List<string>();
            void Write(string relative, string text, string guid = null)
            {
                string path = Path.Combine(package, relative);
                Directory.CreateDirectory(Path.GetDirectoryName(path));
                File.WriteAllText(path, text.Replace("\r\n", "\n"), new UTF8Encoding(false));
                if (guid != null)
                {
                    string meta = path + ".meta";
                    if (!File.Exists(meta) || UnityMeta.GuidOf(meta) != guid) File.WriteAllText(meta, UnityMeta.Text(path, guid));
                }
                else if (!File.Exists(path + ".meta"))
                {
                    File.WriteAllText(path + ".meta", UnityMeta.Text(path, Guid.NewGuid().ToString("N")));
                }
                written.Add(relative);
            }

            written.AddRange(PrimitiveMaterials.WriteAll(package));
            var clips = new GaitClips(map);
            var clipGuids = new Dictionary<LocomotionState, string>();
            foreach (var clip in GaitClips.All)
            {
                Write(ClipPath(clip), GaitClipYaml.Write(clips, clip));
                clipGuids[clip] = GuidOf(package, ClipPath(clip));
            }
            Write(Controller, GaitControllerYaml.Write(clipGuids), ControllerGuid);
            var humanoidGuids = new Dictionary<LocomotionState, string>();
            foreach (var clip in GaitClips.All)
            {
                Write(HumanoidClipPath(clip), HumanoidClipYaml.Write(clips, clip));
                humanoidGuids[clip] = GuidOf(package, HumanoidClipPath(clip));
            }
            Write(HumanoidController, OverrideControllerYaml(clipGuids, humanoidGuids));
            Write(MannequinPrefab, MannequinPrefabYaml(), MannequinPrefabGuid);
            Write(LegsPrefab, LegsPrefabYaml(package), LegsPrefabGuid);
            Write(SampleScene, SampleSceneYaml.Write(package));
            return written;
        }

        /// <summary>
        /// An AnimatorOverrideController (class 221): the package's controller (m_Controller) with each clip
        /// (m_OriginalClip) played as another (m_OverrideClip).
        /// </summary>
        static string OverrideControllerYaml(Dictionary<LocomotionState, string> original, Dictionary<LocomotionState, string> replacement)
        {
            var sb = new StringBuilder(UnityYaml.Header);
            sb.Append(UnityYaml.Document(221, 22100000, "AnimatorOverrideController"));
            sb.Append("  m_ObjectHideFlags: 0\n  m_CorrespondingSourceObject: {fileID: 0}\n  m_PrefabInstance: {fileID: 0}\n  m_PrefabAsset: {fileID: 0}\n");
            sb.Append("  m_Name: HeadGait Legs Humanoid\n  m_Controller: ").Append(UnityYaml.Ref(GaitControllerYaml.ControllerId, ControllerGuid, 2)).Append("\n  m_Clips:\n");
            foreach (var clip in GaitClips.All)
            {
                sb.Append("  - m_OriginalClip: ").Append(UnityYaml.Ref(7400000, original[clip], 2)).Append('\n');
                sb.Append("    m_OverrideClip: ").Append(UnityYaml.Ref(7400000, replacement[clip], 2)).Append('\n');
            }
            return sb.ToString();
        }

        public static string GuidOf(string package, string relative)
        {
            string meta = Path.Combine(package, relative + ".meta");
            return UnityMeta.GuidOf(meta) ?? throw new InvalidOperationException($"{meta}: missing or without a guid");
        }

        /// <summary>The mannequin's bones and primitive meshes (<see cref="Mannequin.Parts"/>) under <paramref name="root"/>.</summary>
        public static void AddMannequin(UnityHierarchyYaml h, string root)
        {
            string P(string path) => root.Length == 0 ? path : path.Length == 0 ? root : root + "/" + path;
            foreach (var part in Mannequin.Parts())
            {
                if (part.Primitive is MannequinPrimitive primitive)
                    h.AddMesh(P(part.ParentPath), part.Name, Mesh(primitive), part.Position, part.Scale, PrimitiveMaterials.Mannequin);
                else
                    h.Add(P(part.Path), part.Name, part.Position, part.Euler);
            }
        }

        /// <summary>Unity's built-in mesh of a primitive.</summary>
        static int Mesh(MannequinPrimitive p) => p == MannequinPrimitive.Cube ? UnityHierarchyYaml.Cube : p == MannequinPrimitive.Sphere ? UnityHierarchyYaml.Sphere : UnityHierarchyYaml.Capsule;

        /// <summary>An Animator (95) playing the package's controller on the rig below it (Generic: no Avatar).</summary>
        public static long AddAnimator(UnityHierarchyYaml h, string path)
            => h.AddComponent(path, 95, "Animator", "Animator",
                "  serializedVersion: 4\n  m_Avatar: {fileID: 0}\n  m_Controller: " + UnityYaml.Ref(GaitControllerYaml.ControllerId, ControllerGuid, 2) + "\n" +
                "  m_CullingMode: 0\n  m_UpdateMode: 0\n  m_ApplyRootMotion: 0\n  m_LinearVelocityBlending: 0\n  m_StabilizeFeet: 0\n" +
                "  m_WarningMessage: \n  m_HasTransformHierarchy: 1\n  m_AllowConstantClipSamplingOptimization: 1\n  m_KeepAnimatorStateOnDisable: 0\n", true);

        /// <summary>
        /// A FollowHead with its defaults: follows the main camera (the XR camera is tagged MainCamera), feet at world height 0,
        /// heading smoothed over 0.1 s.
        /// </summary>
        public static long AddFollowHead(UnityHierarchyYaml h, string path, string package)
            => h.AddScript(path, "FollowHead", GuidOf(package, FollowHeadScript),
                "  head: {fileID: 0}\n  floor: {fileID: 0}\n  floorHeight: 0\n  positionSmoothing: 0\n  headingSmoothing: 0.1\n");

        static string MannequinPrefabYaml()
        {
            var h = new UnityHierarchyYaml(MannequinRoot);
            h.Add("", MannequinRoot);
            AddAnimator(h, "");
            AddMannequin(h, "");
            return h.Write();
        }

        static string LegsPrefabYaml(string package)
        {
            var h = new UnityHierarchyYaml(LegsRoot);
            h.Add("", LegsRoot);
            h.Add(AvatarName, AvatarName);
            long animator = AddAnimator(h, AvatarName);
            AddMannequin(h, AvatarName);
            long legs = h.AddScript("", "GaitLegAnimator", GuidOf(package, GaitLegAnimatorScript),
                "  animator: " + UnityYaml.Ref(animator) + "\n  classifier: 0\n  corTemplate: " + UnityYaml.Ref(TextAssetId, GuidOf(package, CorTemplate), 3) + "\n");
            h.AddScript("", "HeadImuSource", GuidOf(package, HeadImuSourceScript), "  target: " + UnityYaml.Ref(legs) + "\n  mode: 0\n");
            AddFollowHead(h, "", package);
            return h.Write();
        }
    }
}
