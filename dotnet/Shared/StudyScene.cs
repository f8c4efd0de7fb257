using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace HeadGait.Tooling
{
    /// <summary>
    /// Writes the study sample's scene (Samples~/Study/Study.unity) as Unity YAML, so that its file IDs stay consistent
    /// and it needs no editor to make: the paper's outdoor walk, a 16 m path from Start to Turn (8 m) and back to End,
    /// crossing a bridge over a pit both ways, built only from Unity's built-in cube and cylinder meshes; the study
    /// objects (runner, operator view, avatar condition switcher, SSQ panel); the block avatar (unanimated boxes); the
    /// humanoid avatar as an instance of the package's "HeadGait Legs" prefab; a minimal camera rig to replace by the
    /// project's XR Origin. The document layout (file header, scene settings, GameObject/Transform/MeshFilter/
    /// MeshRenderer/MonoBehaviour/PrefabInstance records, built-in mesh references {fileID: 10202 cube, 10206 cylinder,
    /// guid: 0000000000000000e000000000000000} and the package's materials, which render in the built-in pipeline and URP, PrimitiveMaterials)
    /// follows real scenes, e.g. Unity-Technologies/XR-Interaction-Toolkit-Examples VR/Assets/Scenes/UICanvas.unity.
    /// Fields left out take Unity's defaults when the scene loads.
    /// </summary>
    public static class StudyScene
    {
        /// <summary>The humanoid condition is the drop-in prefab, Runtime/Prefabs/HeadGait Legs.prefab.</summary>
        public const string HumanoidPrefabGuid = GaitAssetFiles.LegsPrefabGuid;

        public const double PathHalfLength = 8, PitStart = 3, PitEnd = 5, PitDepth = 6;
        const int Cube = 10202, Cylinder = 10206;

        /// <summary>The script GUIDs the scene refers to, read from the scripts' .meta files.</summary>
        public sealed class Scripts
        {
            public string Runner, OperatorView, Switcher, SsqPanel, FollowHead;
        }

        public static string PathIn(string package) => System.IO.Path.Combine(package, "Samples~", "Study", "Study.unity");

        /// <summary>Reads the GUIDs of the scripts the scene uses from their .meta files in the package.</summary>
        public static Scripts ScriptsIn(string package)
        {
            string Guid(params string[] parts) => UnityMeta.GuidOf(System.IO.Path.Combine(package, System.IO.Path.Combine(parts)) + ".meta")
                                                  ?? throw new System.IO.InvalidDataException($"{System.IO.Path.Combine(parts)}.meta in {package} has no guid line.");
            return new Scripts
            {
                Runner = Guid("Runtime", "Components", "Study", "StudyRunner.cs"),
                OperatorView = Guid("Runtime", "Components", "Study", "StudyOperatorView.cs"),
                Switcher = Guid("Runtime", "Components", "Study", "AvatarConditionSwitcher.cs"),
                SsqPanel = Guid("Samples~", "Study", "SsqPanel.cs"),
                FollowHead = Guid("Runtime", "Components", "FollowHead.cs"),
            };
        }

        public static string Yaml(Scripts scripts)
        {
            var w = new Writer();
            w.Header();
            var sun = w.Object("Sun", null, P(0, 3, 0), (50, -30, 0), (1, 1, 1));
            w.Light(sun);

            var world = w.Object("Path World", null, P(0, 0, 0));
            // Ground: everything but the pit (x -4..4, z 3..5), as thin boxes with their top at y = 0.
            w.Box("Ground South", world, P(0, -0.05, (PitStart - 20) / 2), S(40, 0.1, PitStart + 20), PrimitiveMaterials.Ground);
            w.Box("Ground North", world, P(0, -0.05, PitEnd + 12.5), S(40, 0.1, 25), PrimitiveMaterials.Ground);
            w.Box("Ground West of Pit", world, P(-12, -0.05, 4), S(16, 0.1, PitEnd - PitStart), PrimitiveMaterials.Ground);
            w.Box("Ground East of Pit", world, P(12, -0.05, 4), S(16, 0.1, PitEnd - PitStart), PrimitiveMaterials.Ground);
            w.Box("Pit Floor", world, P(0, -PitDepth, 4), S(8, 0.1, PitEnd - PitStart), PrimitiveMaterials.Pit);
            w.Box("Pit Wall South", world, P(0, -PitDepth / 2, PitStart + 0.05), S(8, PitDepth, 0.1), PrimitiveMaterials.Pit);
            w.Box("Pit Wall North", world, P(0, -PitDepth / 2, PitEnd - 0.05), S(8, PitDepth, 0.1), PrimitiveMaterials.Pit);
            w.Box("Bridge Deck", world, P(0, -0.05, 4), S(1.6, 0.1, PitEnd - PitStart + 0.6), PrimitiveMaterials.Bridge);
            w.Box("Bridge Rail West", world, P(-0.85, 0.5, 4), S(0.05, 1, PitEnd - PitStart + 0.6), PrimitiveMaterials.Bridge);
            w.Box("Bridge Rail East", world, P(0.85, 0.5, 4), S(0.05, 1, PitEnd - PitStart + 0.6), PrimitiveMaterials.Bridge);
            w.Box("Path", world, P(0, 0.005, PathHalfLength / 2), S(1.4, 0.01, PathHalfLength + 0.6), PrimitiveMaterials.Path);
            Marker(w, world, "Start", -0.4, 0);
            Marker(w, world, "Turn", 0, PathHalfLength);
            Marker(w, world, "End", 0.4, 0);

            var rig = w.Object("Camera Rig (replace with your XR Origin)", null, P(0, 0, -0.5));
            var camera = w.Object("Main Camera", rig, P(0, 1.7, 0), tag: "MainCamera");
            w.Camera(camera);

            var avatars = w.Object("Avatar Conditions", null, P(0, 0, 0));
            var block = w.Object("Block Avatar", avatars, P(0, 0, -0.5), active: false);
            w.Box("Torso", block, P(0, 1.2, 0), S(0.4, 0.6, 0.2), PrimitiveMaterials.BlockAvatar);
            w.Box("Hips", block, P(0, 0.85, 0), S(0.36, 0.15, 0.2), PrimitiveMaterials.BlockAvatar);
            w.Box("Left Leg", block, P(-0.1, 0.4, 0), S(0.14, 0.8, 0.14), PrimitiveMaterials.BlockAvatar);
            w.Box("Right Leg", block, P(0.1, 0.4, 0), S(0.14, 0.8, 0.14), PrimitiveMaterials.BlockAvatar);
            w.Box("Left Foot", block, P(-0.1, 0.04, 0.06), S(0.12, 0.08, 0.26), PrimitiveMaterials.BlockAvatar);
            w.Box("Right Foot", block, P(0.1, 0.04, 0.06), S(0.12, 0.08, 0.26), PrimitiveMaterials.BlockAvatar);
            // The blocks are not animated, but they walk with the participant like the humanoid does.
            w.Mono(block, w.Id(), scripts.FollowHead, FollowHeadFields(camera.Transform));
            var humanoid = w.Object("Humanoid Avatar", avatars, P(0, 0, -0.5), active: false);
            // The prefab's own FollowHead (on its root) follows this scene's camera too.
            long followInPrefab = UnityHierarchyYaml.Id(GaitAssetFiles.LegsRoot, "", "FollowHead");
            w.PrefabInstance(humanoid, HumanoidPrefabGuid, UnityHierarchyYaml.Id(GaitAssetFiles.LegsRoot, "", "Transform"),
                (followInPrefab, "head", $"{{fileID: {camera.Transform}}}"));

            var study = w.Object("Study", null, P(0, 0, 0));
            long runner = w.Id(), view = w.Id(), switcher = w.Id();
            w.Mono(study, runner, scripts.Runner,
                "  dataFolder: \n  conditions:\n  - no-avatar\n  - block-avatar\n  - humanoid-avatar\n  pathLengthMeters: 16\n  restSeconds: 120\n" +
                $"  humanoidClassifier: cor\n  avatars: {{fileID: {switcher}}}\n");
            w.Mono(study, view, scripts.OperatorView, $"  runner: {{fileID: {runner}}}\n  width: 460\n");
            w.Mono(study, switcher, scripts.Switcher,
                "  avatars:\n  - condition: no-avatar\n    root: {fileID: 0}\n" +
                $"  - condition: block-avatar\n    root: {{fileID: {block.GameObject}}}\n" +
                $"  - condition: humanoid-avatar\n    root: {{fileID: {humanoid.GameObject}}}\n");

            // The SSQ panel floats at eye height beyond End, facing the participant coming back from Turn.
            var panel = w.Object("SSQ Panel", null, P(0, 1.5, -1.5), (0, 180, 0));
            w.Mono(panel, w.Id(), scripts.SsqPanel, $"  runner: {{fileID: {runner}}}\n  size: {{x: 900, y: 520}}\n");
            return w.ToString();
        }

        /// <summary>FollowHead's fields (as in the drop-in prefab, <see cref="GaitAssetFiles.AddFollowHead"/>) following a given head.</summary>
        static string FollowHeadFields(long head)
            => $"  head: {{fileID: {head}}}\n  floor: {{fileID: 0}}\n  floorHeight: 0\n  positionSmoothing: 0\n  headingSmoothing: 0.1\n";

        static void Marker(Writer w, Node parent, string name, double x, double z)
        {
            var m = w.Object(name, parent, P(x, 0, z));
            w.Box(name + " Pad", m, P(0, 0.012, 0), S(0.6, 0.01, 0.6), PrimitiveMaterials.Marker);
            w.Box(name + " Post", m, P(0, 0.6, 0.45), S(0.08, 0.6, 0.08), PrimitiveMaterials.Marker, Cylinder);
        }

        static (double, double, double) P(double x, double y, double z) => (x, y, z);
        static (double, double, double) S(double x, double y, double z) => (x, y, z);

        public sealed class Node
        {
            public long GameObject, Transform;
            public readonly List<long> Children = new List<long>();
            public int Order;
        }

        sealed class Writer
        {
            readonly StringBuilder head = new StringBuilder();
            readonly List<(Node node, string gameObject, List<string> components, string transform)> nodes = new List<(Node, string, List<string>, string)>();
            readonly StringBuilder tail = new StringBuilder();
            readonly Dictionary<Node, (Node parent, (double, double, double) p, (double, double, double) e, (double, double, double) s)> placement = new Dictionary<Node, (Node, (double, double, double), (double, double, double), (double, double, double))>();
            readonly Dictionary<Node, List<string>> extra = new Dictionary<Node, List<string>>();
            readonly Dictionary<Node, (string name, string tag, bool active, List<long> components)> meta = new Dictionary<Node, (string, string, bool, List<long>)>();
            readonly List<Node> order = new List<Node>();
            int roots;
            long next = 1000;

            public long Id() => next += 2;

            const string Base = "  m_ObjectHideFlags: 0\n  m_CorrespondingSourceObject: {fileID: 0}\n  m_PrefabInstance: {fileID: 0}\n  m_PrefabAsset: {fileID: 0}\n";

            public void Header()
            {
                head.Append("%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n");
                head.Append(UnityYaml.SceneSettings);
            }

            public Node Object(string name, Node parent, (double, double, double) position, (double, double, double)? euler = null, (double, double, double)? scale = null, string tag = "Untagged", bool active = true)
            {
                var n = new Node { GameObject = Id(), Transform = Id() };
                if (parent != null)
                {
                    n.Order = parent.Children.Count;
                    parent.Children.Add(n.Transform);
                }
                else n.Order = roots++;
                placement[n] = (parent, position, euler ?? (0, 0, 0), scale ?? (1, 1, 1));
                meta[n] = (name, tag, active, new List<long> { n.Transform });
                extra[n] = new List<string>();
                order.Add(n);
                return n;
            }

            public void Box(string name, Node parent, (double, double, double) position, (double, double, double) scale, PrimitiveMaterials.Material material, int mesh = Cube)
            {
                var n = Object(name, parent, position, null, scale);
                long filter = Id(), renderer = Id();
                meta[n].components.Add(filter);
                meta[n].components.Add(renderer);
                extra[n].Add($"--- !u!33 &{filter}\nMeshFilter:\n{Base}  m_GameObject: {{fileID: {n.GameObject}}}\n  m_Mesh: {{fileID: {mesh}, guid: 0000000000000000e000000000000000, type: 0}}\n");
                extra[n].Add($"--- !u!23 &{renderer}\nMeshRenderer:\n{Base}  m_GameObject: {{fileID: {n.GameObject}}}\n  m_Enabled: 1\n  m_CastShadows: 1\n  m_ReceiveShadows: 1\n" +
                             "  m_Materials:\n  - " + material.Ref + "\n");
            }

            public void Light(Node n)
            {
                long id = Id();
                meta[n].components.Add(id);
                extra[n].Add($"--- !u!108 &{id}\nLight:\n{Base}  m_GameObject: {{fileID: {n.GameObject}}}\n  m_Enabled: 1\n  serializedVersion: 10\n  m_Type: 1\n" +
                             "  m_Color: {r: 1, g: 0.95686275, b: 0.8392157, a: 1}\n  m_Intensity: 1\n  m_Shadows:\n    m_Type: 2\n");
            }

            public void Camera(Node n)
            {
                long camera = Id(), listener = Id();
                meta[n].components.Add(camera);
                meta[n].components.Add(listener);
                extra[n].Add($"--- !u!20 &{camera}\nCamera:\n{Base}  m_GameObject: {{fileID: {n.GameObject}}}\n  m_Enabled: 1\n  serializedVersion: 2\n" +
                             "  m_ClearFlags: 1\n  m_BackGroundColor: {r: 0.19215687, g: 0.3019608, b: 0.4745098, a: 0}\n  near clip plane: 0.05\n  far clip plane: 1000\n  field of view: 60\n  m_Depth: -1\n");
                extra[n].Add($"--- !u!81 &{listener}\nAudioListener:\n{Base}  m_GameObject: {{fileID: {n.GameObject}}}\n  m_Enabled: 1\n");
            }

            public void Mono(Node n, long id, string scriptGuid, string fields)
            {
                meta[n].components.Add(id);
                extra[n].Add($"--- !u!114 &{id}\nMonoBehaviour:\n{Base}  m_GameObject: {{fileID: {n.GameObject}}}\n  m_Enabled: 1\n  m_EditorHideFlags: 0\n" +
                             $"  m_Script: {{fileID: 11500000, guid: {scriptGuid}, type: 3}}\n  m_Name: \n  m_EditorClassIdentifier: \n{fields}");
            }

            /// <summary>
            /// An instance of a prefab (fileID 100100000 is a prefab asset's own record) under a scene object, at the parent's
            /// origin, with object-reference overrides (target fileID in the prefab, property, reference). Its root Transform
            /// appears in the scene as a `stripped` Transform (only its links to the source object and the instance), which
            /// the parent lists among its children as Unity does.
            /// </summary>
            public void PrefabInstance(Node parent, string prefabGuid, long rootTransformInPrefab, params (long target, string property, string reference)[] references)
            {
                long id = Id(), stripped = Id();
                parent.Children.Add(stripped);
                var sb = new StringBuilder();
                sb.Append($"--- !u!1001 &{id}\nPrefabInstance:\n  m_ObjectHideFlags: 0\n  serializedVersion: 2\n  m_Modification:\n    serializedVersion: 3\n" +
                          $"    m_TransformParent: {{fileID: {parent.Transform}}}\n    m_Modifications:\n");
                void Modify(long target, string property, string value, string reference)
                    => sb.Append($"    - target: {{fileID: {target}, guid: {prefabGuid}, type: 3}}\n      propertyPath: {property}\n" +
                                 $"      value: {value}\n      objectReference: {reference}\n");
                foreach (var axis in new[] { "x", "y", "z" }) Modify(rootTransformInPrefab, "m_LocalPosition." + axis, "0", "{fileID: 0}");
                Modify(rootTransformInPrefab, "m_RootOrder", (parent.Children.Count - 1).ToString(CultureInfo.InvariantCulture), "{fileID: 0}");
                foreach (var (target, property, reference) in references) Modify(target, property, "", reference);
                sb.Append("    m_RemovedComponents: []\n    m_RemovedGameObjects: []\n    m_AddedGameObjects: []\n    m_AddedComponents: []\n");
                sb.Append($"  m_SourcePrefab: {{fileID: 100100000, guid: {prefabGuid}, type: 3}}\n");
                sb.Append($"--- !u!4 &{stripped} stripped\nTransform:\n  m_CorrespondingSourceObject: {{fileID: {rootTransformInPrefab}, guid: {prefabGuid}, type: 3}}\n" +
                          $"  m_PrefabInstance: {{fileID: {id}}}\n  m_PrefabAsset: {{fileID: 0}}\n");
                tail.Append(sb);
            }

            static string F(double v) => v.ToString("0.###", CultureInfo.InvariantCulture);

            static string Rotation((double x, double y, double z) e)
            {
                // Unity's Euler order (Z, then X, then Y), as a quaternion.
                double cx = System.Math.Cos(e.x * System.Math.PI / 360), sx = System.Math.Sin(e.x * System.Math.PI / 360);
                double cy = System.Math.Cos(e.y * System.Math.PI / 360), sy = System.Math.Sin(e.y * System.Math.PI / 360);
                double cz = System.Math.Cos(e.z * System.Math.PI / 360), sz = System.Math.Sin(e.z * System.Math.PI / 360);
                double x = sx * cy * cz + cx * sy * sz, y = cx * sy * cz - sx * cy * sz, z = cx * cy * sz - sx * sy * cz, w = cx * cy * cz + sx * sy * sz;
                return $"{{x: {x.ToString("0.#######", CultureInfo.InvariantCulture)}, y: {y.ToString("0.#######", CultureInfo.InvariantCulture)}, z: {z.ToString("0.#######", CultureInfo.InvariantCulture)}, w: {w.ToString("0.#######", CultureInfo.InvariantCulture)}}}";
            }

            public override string ToString()
            {
                var sb = new StringBuilder(head.ToString());
                foreach (var n in order)
                {
                    var (name, tag, active, components) = meta[n];
                    var (parent, p, e, s) = placement[n];
                    sb.Append($"--- !u!1 &{n.GameObject}\nGameObject:\n{Base}  serializedVersion: 6\n  m_Component:\n");
                    foreach (long c in components) sb.Append($"  - component: {{fileID: {c}}}\n");
                    sb.Append($"  m_Layer: 0\n  m_Name: {name}\n  m_TagString: {tag}\n  m_Icon: {{fileID: 0}}\n  m_NavMeshLayer: 0\n  m_StaticEditorFlags: 0\n  m_IsActive: {(active ? 1 : 0)}\n");
                    sb.Append($"--- !u!4 &{n.Transform}\nTransform:\n{Base}  m_GameObject: {{fileID: {n.GameObject}}}\n  m_LocalRotation: {Rotation(e)}\n" +
                              $"  m_LocalPosition: {{x: {F(p.Item1)}, y: {F(p.Item2)}, z: {F(p.Item3)}}}\n  m_LocalScale: {{x: {F(s.Item1)}, y: {F(s.Item2)}, z: {F(s.Item3)}}}\n");
                    if (n.Children.Count == 0) sb.Append("  m_Children: []\n");
                    else
                    {
                        sb.Append("  m_Children:\n");
                        foreach (long c in n.Children) sb.Append($"  - {{fileID: {c}}}\n");
                    }
                    sb.Append($"  m_Father: {{fileID: {(parent == null ? 0 : parent.Transform)}}}\n  m_RootOrder: {n.Order}\n  m_LocalEulerAnglesHint: {{x: {F(e.Item1)}, y: {F(e.Item2)}, z: {F(e.Item3)}}}\n");
                    foreach (var x in extra[n]) sb.Append(x);
                }
                sb.Append(tail);
                return sb.ToString();
            }
        }
    }
}
