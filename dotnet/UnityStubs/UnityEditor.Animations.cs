// Stand-ins for the editor API that builds Animator Controllers (namespace UnityEditor.Animations) and the asset database
// calls it makes, after UnityCsReference (repo Unity-Technologies/UnityCsReference, file named beside each member).
// Members with a C# body in Unity (AddLayer, AddParameter, AddState, AddTransition, AddCondition, CreateAnimatorControllerAtPath)
// do what that body does; `extern` (native) properties are plain storage here. The stand-ins record what was built
// (AssetDatabase keeps the objects created at each path), so a test can read the controller back as the editor built it.
using System;
using System.Collections.Generic;
using UnityEngine;
using Object = UnityEngine.Object;

namespace UnityEditor.Animations
{
    // Unity's editor code copies arrays in and out of native code and grows them with ArrayUtility.Add
    // (Editor/Mono/Utils/ArrayUtility.cs); the stand-ins do the same with these.
    internal static class Arrays
    {
        internal static T[] Copy<T>(T[] array) => array == null ? new T[0] : (T[])array.Clone();

        internal static T[] Append<T>(T[] array, T item)
        {
            var grown = new T[array.Length + 1];
            Array.Copy(array, grown, array.Length);
            grown[array.Length] = item;
            return grown;
        }
    }

    // Editor/Mono/Animation/StateMachine.bindings.cs: enum AnimatorConditionMode (If = 1, IfNot = 2, Greater = 3, Less = 4,
    // Equals = 6, NotEqual = 7; 5 was ExitTime).
    public enum AnimatorConditionMode
    {
        If = 1,
        IfNot = 2,
        Greater = 3,
        Less = 4,
        Equals = 6,
        NotEqual = 7,
    }

    // Editor/Mono/Animation/StateMachine.bindings.cs: enum TransitionInterruptionSource, declared in this order (0..4).
    public enum TransitionInterruptionSource
    {
        None,
        Source,
        Destination,
        SourceThenDestination,
        DestinationThenSource,
    }

    // Editor/Mono/Animation/StateMachine.bindings.cs: struct AnimatorCondition { mode, parameter, threshold }.
    public struct AnimatorCondition
    {
        public AnimatorConditionMode mode { get; set; }
        public string parameter { get; set; }
        public float threshold { get; set; }
    }

    // Editor/Mono/Animation/StateMachine.bindings.cs (native properties) and StateMachine.cs (AddCondition).
    public class AnimatorTransitionBase : Object
    {
        AnimatorCondition[] conditionList = new AnimatorCondition[0];

        protected AnimatorTransitionBase() { }

        public bool solo { get; set; }
        public bool mute { get; set; }
        public bool isExit { get; set; }
        public AnimatorStateMachine destinationStateMachine { get; set; }
        public AnimatorState destinationState { get; set; }

        // extern AnimatorCondition[] conditions { get; set; }: marshalled, so a caller holds a copy.
        public AnimatorCondition[] conditions
        {
            get => Arrays.Copy(conditionList);
            set => conditionList = Arrays.Copy(value);
        }

        // StateMachine.cs: AddCondition(AnimatorConditionMode mode, float threshold, string parameter) appends one condition.
        public void AddCondition(AnimatorConditionMode mode, float threshold, string parameter)
        {
            conditions = Arrays.Append(conditions, new AnimatorCondition { mode = mode, parameter = parameter, threshold = threshold });
        }
    }

    // Editor/Mono/Animation/StateMachine.bindings.cs: class AnimatorTransition (entry and state machine transitions).
    public class AnimatorTransition : AnimatorTransitionBase { }

    // Editor/Mono/Animation/StateMachine.bindings.cs: class AnimatorStateTransition. The native constructor's defaults are not
    // in the C# source; these are the values a transition made in the Animator window is saved with (duration 0.25 s, exit
    // time 0.75, ordered interruption and can-transition-to-self on, interruption None), so a builder that leaves one unset
    // is seen to.
    public class AnimatorStateTransition : AnimatorTransitionBase
    {
        public float duration { get; set; } = 0.25f;
        public float offset { get; set; }
        public TransitionInterruptionSource interruptionSource { get; set; } = TransitionInterruptionSource.None;
        public bool orderedInterruption { get; set; } = true;
        public float exitTime { get; set; } = 0.75f;
        public bool hasExitTime { get; set; } = true;
        public bool hasFixedDuration { get; set; } = true;
        public bool canTransitionToSelf { get; set; } = true;
    }

    // Editor/Mono/Animation/StateMachine.bindings.cs (native properties) and StateMachine.cs (AddTransition).
    public class AnimatorState : Object
    {
        AnimatorStateTransition[] transitionList = new AnimatorStateTransition[0];

        public Motion motion { get; set; }
        public float speed { get; set; } = 1;
        public float cycleOffset { get; set; }
        public bool mirror { get; set; }
        public bool iKOnFeet { get; set; }
        public bool writeDefaultValues { get; set; } = true;
        public string tag { get; set; } = "";
        public string timeParameter { get; set; } = "";
        public bool timeParameterActive { get; set; }

        // extern AnimatorStateTransition[] transitions { get; set; }: a caller holds a copy of the array.
        public AnimatorStateTransition[] transitions
        {
            get => Arrays.Copy(transitionList);
            set => transitionList = Arrays.Copy(value);
        }

        // StateMachine.cs: AddTransition(AnimatorStateTransition) appends it to transitions.
        public void AddTransition(AnimatorStateTransition transition)
        {
            transitions = Arrays.Append(transitions, transition);
        }

        // StateMachine.cs: AddTransition(AnimatorState destinationState) = CreateTransition(false) (hasExitTime false,
        // hasFixedDuration true, added to this state's asset), destinationState set, then AddTransition(transition).
        public AnimatorStateTransition AddTransition(AnimatorState destinationState)
        {
            var transition = new AnimatorStateTransition { hasExitTime = false, hasFixedDuration = true };
            if (AssetDatabase.GetAssetPath(this) != "") AssetDatabase.AddObjectToAsset(transition, AssetDatabase.GetAssetPath(this));
            transition.destinationState = destinationState;
            AddTransition(transition);
            return transition;
        }
    }

    // Editor/Mono/Animation/StateMachine.bindings.cs: struct ChildAnimatorState { state, position }.
    public struct ChildAnimatorState
    {
        public AnimatorState state { get; set; }
        public Vector3 position { get; set; }
    }

    // Editor/Mono/Animation/StateMachine.bindings.cs (native properties) and StateMachine.cs (AddState).
    public class AnimatorStateMachine : Object
    {
        ChildAnimatorState[] stateList = new ChildAnimatorState[0];
        AnimatorStateTransition[] anyList = new AnimatorStateTransition[0];
        AnimatorTransition[] entryList = new AnimatorTransition[0];

        public ChildAnimatorState[] states
        {
            get => Arrays.Copy(stateList);
            set => stateList = Arrays.Copy(value);
        }

        public AnimatorState defaultState { get; set; }
        public Vector3 anyStatePosition { get; set; }
        public Vector3 entryPosition { get; set; }
        public Vector3 exitPosition { get; set; }

        public AnimatorStateTransition[] anyStateTransitions
        {
            get => Arrays.Copy(anyList);
            set => anyList = Arrays.Copy(value);
        }

        public AnimatorTransition[] entryTransitions
        {
            get => Arrays.Copy(entryList);
            set => entryList = Arrays.Copy(value);
        }

        // extern string MakeUniqueStateName(string name): native; here a taken name gets " 0", " 1", ... appended.
        public string MakeUniqueStateName(string name)
        {
            string unique = name;
            for (int i = 0; Array.Exists(stateList, c => c.state.name == unique); i++) unique = name + " " + i;
            return unique;
        }

        // StateMachine.cs: AddState(string name, Vector3 position) makes a state with a unique name, adds it to this state
        // machine's asset and to states at that position.
        public AnimatorState AddState(string name, Vector3 position)
        {
            var state = new AnimatorState { name = MakeUniqueStateName(name) };
            if (AssetDatabase.GetAssetPath(this) != "") AssetDatabase.AddObjectToAsset(state, AssetDatabase.GetAssetPath(this));
            AddState(state, position);
            return state;
        }

        // StateMachine.cs: AddState(AnimatorState state, Vector3 position); a state already present is discarded (with a warning).
        public void AddState(AnimatorState state, Vector3 position)
        {
            if (Array.Exists(stateList, c => c.state == state)) return;
            states = Arrays.Append(states, new ChildAnimatorState { state = state, position = position });
        }
    }

    // Editor/Mono/Animation/AnimatorController.bindings.cs: enum AnimatorLayerBlendingMode { Override, Additive }.
    public enum AnimatorLayerBlendingMode
    {
        Override,
        Additive,
    }

    // Editor/Mono/Animation/AnimatorControllerLayer.bindings.cs: class AnimatorControllerLayer, marshalled as a struct
    // ([NativeAsStruct]): AnimatorController.layers hands out copies, so a change to a layer takes a `layers = ...` to keep.
    public class AnimatorControllerLayer
    {
        public string name { get; set; } = "";
        public AnimatorStateMachine stateMachine { get; set; }
        public AnimatorLayerBlendingMode blendingMode { get; set; }
        public int syncedLayerIndex { get; set; } = -1;
        public bool iKPass { get; set; }
        public float defaultWeight { get; set; }
        public bool syncedLayerAffectsTiming { get; set; }

        internal AnimatorControllerLayer Copy() => (AnimatorControllerLayer)MemberwiseClone();
    }

    // Editor/Mono/Animation/AnimatorController.bindings.cs (layers, parameters, MakeUnique*Name) and AnimatorController.cs
    // (AddLayer, AddParameter, CreateAnimatorControllerAtPath).
    public sealed class AnimatorController : RuntimeAnimatorController
    {
        AnimatorControllerLayer[] layerList = new AnimatorControllerLayer[0];
        AnimatorControllerParameter[] parameterList = new AnimatorControllerParameter[0];

        // Native GetLayers/SetLayers: marshalled copies each way.
        public AnimatorControllerLayer[] layers
        {
            get => Array.ConvertAll(layerList, l => l.Copy());
            set => layerList = Array.ConvertAll(value ?? new AnimatorControllerLayer[0], l => l.Copy());
        }

        // Native GetParameters/SetParameters: marshalled copies each way.
        public AnimatorControllerParameter[] parameters
        {
            get => Array.ConvertAll(parameterList, Copy);
            set => parameterList = Array.ConvertAll(value ?? new AnimatorControllerParameter[0], Copy);
        }

        static AnimatorControllerParameter Copy(AnimatorControllerParameter p) => new AnimatorControllerParameter
        {
            name = p.name, type = p.type, defaultFloat = p.defaultFloat, defaultInt = p.defaultInt, defaultBool = p.defaultBool,
        };

        // extern MakeUniqueParameterName / MakeUniqueLayerName: native; here a taken name gets " 0", " 1", ... appended.
        public string MakeUniqueParameterName(string name) => Unique(name, n => Array.Exists(parameterList, p => p.name == n));
        public string MakeUniqueLayerName(string name) => Unique(name, n => Array.Exists(layerList, l => l.name == n));

        static string Unique(string name, Predicate<string> taken)
        {
            string unique = name;
            for (int i = 0; taken(unique); i++) unique = name + " " + i;
            return unique;
        }

        // AnimatorController.cs: AddLayer(string name): a layer with a unique name and a new state machine of the same
        // name, added to this controller's asset.
        public void AddLayer(string name)
        {
            var layer = new AnimatorControllerLayer { name = MakeUniqueLayerName(name), stateMachine = new AnimatorStateMachine() };
            layer.stateMachine.name = layer.name;
            if (AssetDatabase.GetAssetPath(this) != "") AssetDatabase.AddObjectToAsset(layer.stateMachine, AssetDatabase.GetAssetPath(this));
            AddLayer(layer);
        }

        // AnimatorController.cs: AddLayer(AnimatorControllerLayer layer) appends it to layers.
        public void AddLayer(AnimatorControllerLayer layer)
        {
            layers = Arrays.Append(layers, layer);
        }

        // AnimatorController.cs: AddParameter(string name, AnimatorControllerParameterType type): a unique name, then appended.
        public void AddParameter(string name, AnimatorControllerParameterType type)
            => AddParameter(new AnimatorControllerParameter { name = MakeUniqueParameterName(name), type = type });

        public void AddParameter(AnimatorControllerParameter paramater)
        {
            parameters = Arrays.Append(parameters, paramater);
        }

        // RuntimeAnimatorController.animationClips: the clips its layers' states play, each once, in layer and state order.
        internal override AnimationClip[] AnimationClipsOf()
        {
            var clips = new List<AnimationClip>();
            foreach (var layer in layerList)
                foreach (var child in layer.stateMachine?.states ?? new ChildAnimatorState[0])
                    if (child.state?.motion is AnimationClip clip && !clips.Contains(clip)) clips.Add(clip);
            return clips.ToArray();
        }

        // AnimatorController.cs: CreateAnimatorControllerAtPath(string path): a controller named Path.GetFileName(path),
        // created as the asset at path, with one layer "Base Layer".
        public static AnimatorController CreateAnimatorControllerAtPath(string path)
        {
            var controller = new AnimatorController { name = System.IO.Path.GetFileName(path) };
            AssetDatabase.CreateAsset(controller, path);
            controller.AddLayer("Base Layer");
            return controller;
        }
    }
}

namespace UnityEditor
{
    // Editor/Mono/AssetDatabase/AssetDatabase.bindings.cs. Here the "database" is the objects created at each path, in memory.
    public sealed partial class AssetDatabase
    {
        static readonly Dictionary<string, List<Object>> assets = new Dictionary<string, List<Object>>();
        static readonly Dictionary<Object, string> pathOf = new Dictionary<Object, string>();

        // CreateAsset(Object asset, string path): path is project-relative ("Assets/...", with the extension); an asset
        // already at path is replaced.
        public static void CreateAsset(Object asset, string path)
        {
            if (asset == null) throw new ArgumentNullException(nameof(asset));
            if (string.IsNullOrEmpty(path) || !(path.StartsWith("Assets/", StringComparison.Ordinal) || path.StartsWith("Packages/", StringComparison.Ordinal)))
                throw new ArgumentException($"'{path}' is not a path inside the project (Assets/...)", nameof(path));
            DeleteAsset(path);
            assets[path] = new List<Object> { asset };
            pathOf[asset] = path;
        }

        // AddObjectToAsset(Object objectToAdd, string path): the object becomes a sub-asset of the asset at path.
        public static void AddObjectToAsset(Object objectToAdd, string path)
        {
            if (!assets.TryGetValue(path, out var list)) throw new ArgumentException($"no asset at '{path}'", nameof(path));
            if (!list.Contains(objectToAdd)) list.Add(objectToAdd);
            pathOf[objectToAdd] = path;
        }

        // GetAssetPath(Object assetObject): "" for an object that is no asset.
        public static string GetAssetPath(Object assetObject) => assetObject != null && pathOf.TryGetValue(assetObject, out var p) ? p : "";

        // LoadAssetAtPath<T>(string assetPath): the first object of type T at the path, or null.
        public static T LoadAssetAtPath<T>(string assetPath) where T : Object
        {
            if (assetPath != null && assets.TryGetValue(assetPath, out var list))
                foreach (var o in list)
                    if (o is T t) return t;
            return null;
        }

        // DeleteAsset(string path): true when there was an asset to delete.
        public static bool DeleteAsset(string path)
        {
            if (path == null || !assets.TryGetValue(path, out var list)) return false;
            foreach (var o in list) pathOf.Remove(o);
            assets.Remove(path);
            return true;
        }

        // IsValidFolder(string path): a folder of the project: "Assets", "Packages/<name>", or one CreateFolder made (here
        // with any asset under it counting too).
        static readonly HashSet<string> folders = new HashSet<string>();

        public static bool IsValidFolder(string path)
        {
            if (string.IsNullOrEmpty(path)) return false;
            path = path.TrimEnd('/');
            if (path == "Assets" || (path.StartsWith("Packages/", StringComparison.Ordinal) && path.IndexOf('/', 9) < 0) || folders.Contains(path)) return true;
            foreach (var asset in assets.Keys)
                if (asset.StartsWith(path + "/", StringComparison.Ordinal)) return true;
            return false;
        }

        // CreateFolder(string parentFolder, string newFolderName): the new folder's GUID, or "" when the parent is no folder;
        // a name taken already gets " 1", " 2", ... (Unity makes it unique).
        public static string CreateFolder(string parentFolder, string newFolderName)
        {
            if (!IsValidFolder(parentFolder) || string.IsNullOrEmpty(newFolderName)) return "";
            string path = parentFolder.TrimEnd('/') + "/" + newFolderName;
            for (int i = 1; IsValidFolder(path); i++) path = parentFolder.TrimEnd('/') + "/" + newFolderName + " " + i;
            folders.Add(path);
            return Guid.NewGuid().ToString("N");
        }

        // SaveAssets(): writes changed assets to disk; nothing to write here.
        public static void SaveAssets() { }
    }

    // Editor/Mono/Animation/EditorCurveBinding.bindings.cs: struct EditorCurveBinding { path, type, propertyName };
    // FloatCurve(inPath, inType, inPropertyName) makes a float curve's binding.
    public struct EditorCurveBinding
    {
        public string path;
        public string propertyName;
        public Type type { get; set; }

        public static EditorCurveBinding FloatCurve(string inPath, Type inType, string inPropertyName)
            => new EditorCurveBinding { path = inPath, type = inType, propertyName = inPropertyName };
    }

    // Editor/Mono/Animation/AnimationClipSettings.bindings.cs: a class of public fields, marshalled as a struct.
    public class AnimationClipSettings
    {
        public float startTime;
        public float stopTime;
        public float cycleOffset;
        public bool loopTime;
        public bool loopBlend;
        public bool loopBlendOrientation;
        public bool loopBlendPositionY;
        public bool loopBlendPositionXZ;
        public bool keepOriginalOrientation;
        public bool keepOriginalPositionY;
        public bool keepOriginalPositionXZ;
        public bool heightFromFeet;
        public bool mirror;

        internal AnimationClipSettings Copy() => (AnimationClipSettings)MemberwiseClone();
    }

    // Editor/Mono/Animation/AnimationUtility.bindings.cs: the editor curves of a clip (SetEditorCurve adds, replaces or,
    // with a null curve, removes the curve of a binding; the clip keeps a copy) and its settings (copied each way).
    public partial class AnimationUtility
    {
        // What Unity keeps natively in each clip: its editor curves, in the order first set, and its settings.
        sealed class ClipData
        {
            internal readonly List<(EditorCurveBinding Binding, Keyframe[] Keys)> curves = new List<(EditorCurveBinding, Keyframe[])>();
            internal AnimationClipSettings settings = new AnimationClipSettings { stopTime = 1 };
        }

        static readonly System.Runtime.CompilerServices.ConditionalWeakTable<AnimationClip, ClipData> data = new System.Runtime.CompilerServices.ConditionalWeakTable<AnimationClip, ClipData>();

        static ClipData Of(AnimationClip clip) => data.GetValue(clip ?? throw new ArgumentNullException(nameof(clip)), _ => new ClipData());

        public static void SetEditorCurve(AnimationClip clip, EditorCurveBinding binding, AnimationCurve curve)
        {
            var curves = Of(clip).curves;
            int at = curves.FindIndex(c => Same(c.Binding, binding));
            if (curve == null)
            {
                if (at >= 0) curves.RemoveAt(at);
                return;
            }
            if (at >= 0) curves[at] = (binding, curve.keys);
            else curves.Add((binding, curve.keys));
        }

        public static AnimationCurve GetEditorCurve(AnimationClip clip, EditorCurveBinding binding)
        {
            var curves = Of(clip).curves;
            int at = curves.FindIndex(c => Same(c.Binding, binding));
            return at < 0 ? null : new AnimationCurve(curves[at].Keys);
        }

        public static EditorCurveBinding[] GetCurveBindings(AnimationClip clip) => Of(clip).curves.ConvertAll(c => c.Binding).ToArray();

        public static AnimationClipSettings GetAnimationClipSettings(AnimationClip clip) => Of(clip).settings.Copy();

        public static void SetAnimationClipSettings(AnimationClip clip, AnimationClipSettings srcClipInfo) => Of(clip).settings = srcClipInfo.Copy();

        static bool Same(EditorCurveBinding a, EditorCurveBinding b) => a.path == b.path && a.type == b.type && a.propertyName == b.propertyName;
    }

    // Editor/Mono/EditorUtility.cs: SaveFilePanelInProject(title, defaultName, extension, message) returns a project-relative
    // path ("Assets/..."), or "" when cancelled (as here).
    public sealed partial class EditorUtility
    {
        public static string SaveFilePanelInProject(string title, string defaultName, string extension, string message) => "";
    }
}
