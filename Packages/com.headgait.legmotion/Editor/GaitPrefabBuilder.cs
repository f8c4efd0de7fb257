using HeadGait.Unity;
using UnityEditor;
using UnityEngine;

namespace HeadGait.Editor
{
    /// <summary>
    /// Builds the package's two prefabs with Unity's editor API from <see cref="Mannequin.Parts"/>, the facts `headgait
    /// clips` writes the shipped prefabs from: HeadGait Mannequin (an Animator playing the locomotion controller on the
    /// primitive mannequin) and HeadGait Legs (the drop-in: Gait Leg Animator, Head IMU Source and Follow Head on the root,
    /// the mannequin as its Avatar child). The GameObjects are made in the open scene, saved with
    /// PrefabUtility.SaveAsPrefabAsset and destroyed again. API as in UnityCsReference Editor/Mono/Prefabs/PrefabUtility.cs
    /// (SaveAsPrefabAsset), Editor/Mono/SerializedObject.bindings.cs (the components' private serialized fields) and
    /// Runtime/Export/Resources/Resources.cs (GetBuiltinResource, Unity's primitive meshes).
    /// </summary>
    public static class GaitPrefabBuilder
    {
        /// <param name="path">"Assets/.../HeadGait Mannequin.prefab"; a prefab there is replaced.</param>
        /// <param name="controller">The controller its Animator plays (the package's HeadGait Legs.controller).</param>
        /// <param name="material">The material of every mesh (the package's HeadGait Mannequin.mat).</param>
        public static GameObject CreateMannequin(string path, RuntimeAnimatorController controller, Material material)
        {
            var root = new GameObject(Mannequin.PrefabRoot);
            try
            {
                AddAnimator(root, controller);
                AddMannequin(root.transform, material);
                return PrefabUtility.SaveAsPrefabAsset(root, path);
            }
            finally
            {
                Object.DestroyImmediate(root);
            }
        }

        /// <param name="path">"Assets/.../HeadGait Legs.prefab"; a prefab there is replaced.</param>
        /// <param name="corTemplate">The COR template the Gait Leg Animator runs (the package's Models/cor_template.txt).</param>
        public static GameObject CreateLegs(string path, RuntimeAnimatorController controller, Material material, TextAsset corTemplate)
        {
            var root = new GameObject(Mannequin.LegsPrefabRoot);
            try
            {
                var avatar = new GameObject(Mannequin.LegsAvatar);
                avatar.transform.SetParent(root.transform, false);
                var animator = AddAnimator(avatar, controller);
                AddMannequin(avatar.transform, material);
                var legs = root.AddComponent<GaitLegAnimator>();
                Set(legs, ("animator", (Object)animator), ("corTemplate", corTemplate));
                var source = root.AddComponent<HeadImuSource>();
                Set(source, ("target", (Object)legs));
                root.AddComponent<FollowHead>(); // its defaults: the main camera, feet at height 0
                return PrefabUtility.SaveAsPrefabAsset(root, path);
            }
            finally
            {
                Object.DestroyImmediate(root);
            }
        }

        static Animator AddAnimator(GameObject on, RuntimeAnimatorController controller)
        {
            var animator = on.AddComponent<Animator>();
            animator.runtimeAnimatorController = controller;
            return animator;
        }

        /// <summary>The mannequin's bones and meshes under <paramref name="root"/>.</summary>
        static void AddMannequin(Transform root, Material material)
        {
            var byPath = new System.Collections.Generic.Dictionary<string, Transform> { [""] = root };
            foreach (var part in Mannequin.Parts())
            {
                var go = new GameObject(part.Name);
                go.transform.SetParent(byPath[part.ParentPath], false);
                go.transform.localPosition = Vector(part.Position);
                go.transform.localRotation = Quaternion.Euler(Vector(part.Euler));
                go.transform.localScale = Vector(part.Scale);
                byPath[part.Path] = go.transform;
                if (part.Primitive is MannequinPrimitive primitive)
                {
                    go.AddComponent<MeshFilter>().sharedMesh = Resources.GetBuiltinResource<Mesh>(primitive + ".fbx");
                    go.AddComponent<MeshRenderer>().sharedMaterial = material;
                }
            }
        }

        /// <summary>Sets a component's serialized fields by name, as the Inspector would.</summary>
        static void Set(Object component, params (string Field, Object Value)[] fields)
        {
            using (var serialized = new SerializedObject(component))
            {
                foreach (var (field, value) in fields)
                {
                    var property = serialized.FindProperty(field) ?? throw new System.InvalidOperationException($"{component.GetType().Name} has no serialized field '{field}'");
                    property.objectReferenceValue = value;
                }
                serialized.ApplyModifiedPropertiesWithoutUndo();
            }
        }

        static Vector3 Vector(double[] v) => new Vector3((float)v[0], (float)v[1], (float)v[2]);
    }
}
