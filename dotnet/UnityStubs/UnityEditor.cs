// Stand-ins for the UnityEditor members the package's Editor code uses (repo Unity-Technologies/UnityCsReference).
using System;

namespace UnityEditor
{
    // Editor/Mono/MenuItem.cs
    [AttributeUsage(AttributeTargets.Method)] public sealed class MenuItem : Attribute { public MenuItem(string itemName) { } }

    // Editor/Mono/EditorUtility.bindings.cs
    public sealed partial class EditorUtility
    {
        public static string OpenFilePanel(string title, string directory, string extension) => "";
        public static string OpenFolderPanel(string title, string folder, string defaultName) => "";
        public static string SaveFilePanel(string title, string directory, string defaultName, string extension) => "";
        public static bool DisplayDialog(string title, string message, string ok) => true;
    }

    // Editor/Mono/AssetDatabase/AssetDatabase.bindings.cs
    public sealed partial class AssetDatabase
    {
        public static void Refresh() { }
    }
}
