using System.Collections.Generic;
using System.Text;

namespace HeadGait.Tooling
{
    /// <summary>
    /// Builds the YAML of a GameObject hierarchy (a prefab's content or a scene's objects): GameObject (1) with its
    /// m_Component list, Transform (4) with m_Children/m_Father, and further components. Every object's fileID is
    /// <see cref="UnityYaml.StableFileId"/> of the hierarchy's scope, the object's path and its kind, so a regenerated prefab
    /// keeps the IDs that scenes refer to (<see cref="Id"/>). Layout as in prefabs saved by Unity 2021-2022.
    /// </summary>
    public sealed class UnityHierarchyYaml
    {
        /// <summary>Unity's built-in meshes (library 'unity default resources').</summary>
        public const int Cube = 10202, Sphere = 10207, Capsule = 10208, Plane = 10209;

        sealed class Node
        {
            public string Path;
            public string Name;
            public string Parent;
            public string Tag;
            public double[] Position, Euler, Scale;
            public readonly List<long> Components = new List<long>();
            public readonly List<string> Children = new List<string>();
        }

        readonly string scope;
        readonly List<Node> nodes = new List<Node>();
        readonly Dictionary<string, Node> byPath = new Dictionary<string, Node>();
        readonly StringBuilder components = new StringBuilder();

        public UnityHierarchyYaml(string scope)
        {
            this.scope = scope;
        }

        /// <summary>The fileID of an object in a hierarchy: kind "GameObject", "Transform" or a component's name.</summary>
        public static long Id(string scope, string path, string kind) => UnityYaml.StableFileId(scope + ":" + path + "#" + kind);

        public long Id(string path, string kind) => Id(scope, path, kind);

        /// <summary>
        /// Adds a GameObject with a Transform; the path is '/'-joined names below the root ("" for the root); <paramref name="tag"/>
        /// one of the project's tags (Unity's built-in ones: Untagged, MainCamera, ...).
        /// </summary>
        public void Add(string path, string name, double[] position = null, double[] euler = null, double[] scale = null, string tag = "Untagged")
        {
            // A top-level name hangs under the root ("") where there is one (a prefab), else it is a scene root.
            string parent = path.Length == 0 ? null : path.Contains("/") ? path.Substring(0, path.LastIndexOf('/')) : byPath.ContainsKey("") ? "" : null;
            var node = new Node
            {
                Path = path, Name = name, Parent = parent, Tag = tag,
                Position = position ?? new double[3], Euler = euler ?? new double[3], Scale = scale ?? new[] { 1.0, 1, 1 },
            };
            node.Components.Add(Id(path, "Transform"));
            if (parent != null) byPath[parent].Children.Add(path);
            nodes.Add(node);
            byPath[path] = node;
        }

        /// <summary>Adds a component; <paramref name="body"/> is its fields after m_GameObject (two-space indented lines).</summary>
        public long AddComponent(string path, int classId, string type, string kind, string body, bool behaviour)
        {
            long id = Id(path, kind);
            byPath[path].Components.Add(id);
            components.Append(UnityYaml.Document(classId, id, type));
            components.Append("  m_ObjectHideFlags: 0\n  m_CorrespondingSourceObject: {fileID: 0}\n  m_PrefabInstance: {fileID: 0}\n  m_PrefabAsset: {fileID: 0}\n");
            components.Append("  m_GameObject: ").Append(UnityYaml.Ref(Id(path, "GameObject"))).Append('\n');
            if (behaviour) components.Append("  m_Enabled: 1\n");
            components.Append(body);
            return id;
        }

        /// <summary>A MonoBehaviour of a script (its .cs.meta GUID) with serialized fields.</summary>
        public long AddScript(string path, string kind, string scriptGuid, string fields)
            => AddComponent(path, 114, "MonoBehaviour", kind,
                "  m_EditorHideFlags: 0\n  m_Script: " + UnityYaml.Ref(11500000, scriptGuid, 3) + "\n  m_Name: \n  m_EditorClassIdentifier: \n" + fields, true);

        /// <summary>A child GameObject showing a built-in mesh with one of the package's materials (they render in any pipeline).</summary>
        public void AddMesh(string parentPath, string name, int mesh, double[] position, double[] scale, PrimitiveMaterials.Material material)
        {
            string path = parentPath.Length == 0 ? name : parentPath + "/" + name;
            Add(path, name, position, null, scale);
            AddComponent(path, 33, "MeshFilter", "MeshFilter", "  m_Mesh: " + UnityYaml.Ref(mesh, UnityYaml.BuiltinExtraGuid, 0) + "\n", false);
            AddComponent(path, 23, "MeshRenderer", "MeshRenderer",
                "  m_CastShadows: 1\n  m_ReceiveShadows: 1\n  m_DynamicOccludee: 1\n  m_MotionVectors: 1\n  m_LightProbeUsage: 1\n" +
                "  m_ReflectionProbeUsage: 1\n  m_RenderingLayerMask: 1\n  m_RendererPriority: 0\n  m_Materials:\n" +
                "  - " + material.Ref + "\n" +
                "  m_StaticBatchInfo: {firstSubMesh: 0, subMeshCount: 0}\n  m_StaticBatchRoot: {fileID: 0}\n  m_ProbeAnchor: {fileID: 0}\n" +
                "  m_LightProbeVolumeOverride: {fileID: 0}\n  m_SortingLayerID: 0\n  m_SortingLayer: 0\n  m_SortingOrder: 0\n", true);
        }

        public string Write(bool withHeader = true)
        {
            var sb = new StringBuilder(withHeader ? UnityYaml.Header : "");
            foreach (var n in nodes)
            {
                sb.Append(UnityYaml.Document(1, Id(n.Path, "GameObject"), "GameObject"));
                sb.Append("  m_ObjectHideFlags: 0\n  m_CorrespondingSourceObject: {fileID: 0}\n  m_PrefabInstance: {fileID: 0}\n  m_PrefabAsset: {fileID: 0}\n");
                sb.Append("  serializedVersion: 6\n  m_Component:\n");
                foreach (var c in n.Components) sb.Append("  - component: ").Append(UnityYaml.Ref(c)).Append('\n');
                sb.Append("  m_Layer: 0\n  m_Name: ").Append(n.Name).Append("\n  m_TagString: ").Append(n.Tag).Append("\n  m_Icon: {fileID: 0}\n");
                sb.Append("  m_NavMeshLayer: 0\n  m_StaticEditorFlags: 0\n  m_IsActive: 1\n");

                sb.Append(UnityYaml.Document(4, Id(n.Path, "Transform"), "Transform"));
                sb.Append("  m_ObjectHideFlags: 0\n  m_CorrespondingSourceObject: {fileID: 0}\n  m_PrefabInstance: {fileID: 0}\n  m_PrefabAsset: {fileID: 0}\n");
                sb.Append("  m_GameObject: ").Append(UnityYaml.Ref(Id(n.Path, "GameObject"))).Append('\n');
                var q = Quaternion(n.Euler);
                sb.Append($"  m_LocalRotation: {{x: {UnityYaml.Number(q[0])}, y: {UnityYaml.Number(q[1])}, z: {UnityYaml.Number(q[2])}, w: {UnityYaml.Number(q[3])}}}\n");
                sb.Append("  m_LocalPosition: ").Append(UnityYaml.Vector(n.Position[0], n.Position[1], n.Position[2])).Append('\n');
                sb.Append("  m_LocalScale: ").Append(UnityYaml.Vector(n.Scale[0], n.Scale[1], n.Scale[2])).Append('\n');
                sb.Append("  m_Children:");
                if (n.Children.Count == 0) sb.Append(" []");
                sb.Append('\n');
                foreach (var c in n.Children) sb.Append("  - ").Append(UnityYaml.Ref(Id(c, "Transform"))).Append('\n');
                sb.Append("  m_Father: ").Append(UnityYaml.Ref(n.Parent == null ? 0 : Id(n.Parent, "Transform"))).Append('\n');
                sb.Append("  m_RootOrder: ").Append(n.Parent == null ? 0 : byPath[n.Parent].Children.IndexOf(n.Path)).Append('\n');
                sb.Append("  m_LocalEulerAnglesHint: ").Append(UnityYaml.Vector(n.Euler[0], n.Euler[1], n.Euler[2])).Append('\n');
            }
            sb.Append(components);
            return sb.ToString();
        }

        /// <summary>Unity's Euler order (z, then x, then y, applied to the vector: q = y * x * z), degrees.</summary>
        static double[] Quaternion(double[] euler)
        {
            double[] Axis(double deg, int axis)
            {
                double h = deg * System.Math.PI / 360.0;
                var q = new double[] { 0, 0, 0, System.Math.Cos(h) };
                q[axis] = System.Math.Sin(h);
                return q;
            }
            return Multiply(Multiply(Axis(euler[1], 1), Axis(euler[0], 0)), Axis(euler[2], 2));
        }

        static double[] Multiply(double[] a, double[] b) => new[]
        {
            a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
            a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
            a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3],
            a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2],
        };
    }
}
