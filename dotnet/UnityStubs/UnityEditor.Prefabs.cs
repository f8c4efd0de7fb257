// Stand-ins for saving prefabs from the editor, after UnityCsReference: Editor/Mono/Prefabs/PrefabUtility.cs
// (SaveAsPrefabAsset(GameObject instanceRoot, string assetPath[, out bool success]): ArgumentNullException for a null root
// or an empty path, ArgumentException for a path that is not a .prefab in the project; the saved asset's root is
// returned, a different object from the instance) and Editor/Mono/SerializedObject.bindings.cs,
// SerializedProperty.bindings.cs (SerializedObject(Object), FindProperty(string): null for a name that is not a serialized
// field; the value properties; ApplyModifiedPropertiesWithoutUndo writes the changes and says whether there were any).
using System;
using System.Collections.Generic;
using System.Reflection;
using UnityEngine;
using Object = UnityEngine.Object;

namespace UnityEditor
{
    public static class PrefabUtility
    {
        public static GameObject SaveAsPrefabAsset(GameObject instanceRoot, string assetPath) => SaveAsPrefabAsset(instanceRoot, assetPath, out _);

        public static GameObject SaveAsPrefabAsset(GameObject instanceRoot, string assetPath, out bool success)
        {
            if (instanceRoot == null) throw new ArgumentNullException("Parameter root is null");
            if (string.IsNullOrEmpty(assetPath)) throw new ArgumentNullException("path is null or empty");
            if (!assetPath.EndsWith(".prefab", StringComparison.Ordinal)
                || !(assetPath.StartsWith("Assets/", StringComparison.Ordinal) || assetPath.StartsWith("Packages/", StringComparison.Ordinal)))
                throw new ArgumentException("Given path is not valid: '" + assetPath + "'");
            var asset = instanceRoot.CopyForAsset();
            AssetDatabase.CreateAsset(asset, assetPath);
            success = true;
            return asset;
        }
    }

    public class SerializedObject : IDisposable
    {
        readonly List<SerializedProperty> changed = new List<SerializedProperty>();

        public SerializedObject(Object obj) => targetObject = obj ?? throw new ArgumentException("Object to serialize is null");

        public Object targetObject { get; }

        public SerializedProperty FindProperty(string propertyPath)
        {
            for (var type = targetObject.GetType(); type != null && type != typeof(MonoBehaviour) && type != typeof(Object); type = type.BaseType)
            {
                var f = type.GetField(propertyPath ?? "", BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.DeclaredOnly);
                if (f != null && !f.IsInitOnly && (f.IsPublic || f.IsDefined(typeof(SerializeField), false))) return new SerializedProperty(this, f);
            }
            return null;
        }

        internal void Changed(SerializedProperty p)
        {
            if (!changed.Contains(p)) changed.Add(p);
        }

        public bool ApplyModifiedPropertiesWithoutUndo()
        {
            foreach (var p in changed) p.Write();
            bool any = changed.Count > 0;
            changed.Clear();
            return any;
        }

        public bool ApplyModifiedProperties() => ApplyModifiedPropertiesWithoutUndo();

        public void Dispose() { }
    }

    public class SerializedProperty
    {
        readonly SerializedObject owner;
        readonly FieldInfo field;
        object value;

        internal SerializedProperty(SerializedObject owner, FieldInfo field)
        {
            this.owner = owner;
            this.field = field;
            value = field.GetValue(owner.targetObject);
        }

        public string name => field.Name;
        public string propertyPath => field.Name;

        void Set(object v)
        {
            value = v;
            owner.Changed(this);
        }

        internal void Write() => field.SetValue(owner.targetObject, field.FieldType.IsEnum ? Enum.ToObject(field.FieldType, value) : Convert.ChangeType(value, Nullable.GetUnderlyingType(field.FieldType) ?? field.FieldType));

        public Object objectReferenceValue
        {
            get => value as Object;
            set => Set(value);
        }

        public int intValue
        {
            get => Convert.ToInt32(value);
            set => Set(value);
        }

        public float floatValue
        {
            get => Convert.ToSingle(value);
            set => Set(value);
        }

        public bool boolValue
        {
            get => Convert.ToBoolean(value);
            set => Set(value);
        }

        public string stringValue
        {
            get => value as string;
            set => Set(value);
        }
    }
}
