using System.IO;
using System.Text;
using UnityEditor;
using UnityEngine;

namespace HeadGait.Editor
{
    /// <summary>
    /// Tools > HeadGait: evaluate a recording, train a COR template, and build from inside the editor what `headgait clips`
    /// writes into the package: the locomotion Animator Controller, the gait clips, the Humanoid clips with their Animator
    /// Override Controller, and the drop-in and mannequin prefabs.
    /// </summary>
    public static class HeadGaitMenu
    {
        [MenuItem("Tools/HeadGait/Evaluate Recording...")]
        static void Evaluate()
        {
            string csv = EditorUtility.OpenFilePanel("Recording to evaluate (CSV with phase_left/phase_right)", Application.dataPath, "csv");
            if (string.IsNullOrEmpty(csv)) return;
            string tpl = EditorUtility.OpenFolderPanel("Model folder (thr.txt, cor_template.txt, svm.bytes, blstm.bytes)", Path.GetDirectoryName(csv), "");
            if (string.IsNullOrEmpty(tpl)) return;
            try
            {
                var rec = RecordingCsv.Load(csv);
                var report = new StringBuilder($"HeadGait evaluation of {rec.Name} ({rec.Samples.Count} rows, {rec.Warnings.Count} skipped)\n");
                var models = GaitModels.Load(tpl);
                foreach (var problem in models.Problems) report.AppendLine("warning: " + problem);
                foreach (var name in GaitModels.Names) Append(report, ReplayEvaluator.Run(rec, models.Create(name, out _)));
                Debug.Log(report.ToString());
            }
            catch (System.Exception e) when (e is RecordingFormatException || e is IOException || e is System.FormatException)
            {
                EditorUtility.DisplayDialog("HeadGait", e.Message, "OK");
            }
        }

        [MenuItem("Tools/HeadGait/Train THR and COR...")]
        static void Train()
        {
            string folder = EditorUtility.OpenFolderPanel("Folder of labelled recordings (CSV)", Application.dataPath, "");
            if (string.IsNullOrEmpty(folder)) return;
            string output = EditorUtility.OpenFolderPanel("Model folder to write thr.txt and cor_template.txt into", Application.dataPath, "");
            if (string.IsNullOrEmpty(output)) return;
            try
            {
                var recordings = new System.Collections.Generic.List<Recording>();
                foreach (var f in Directory.GetFiles(folder, "*.csv")) recordings.Add(RecordingCsv.Load(f));
                var training = HeadGait.Training.GaitTraining.WithAugmentation(recordings, HeadGait.Training.GaitTraining.DefaultAugmentedCopies);
                var map = HeadGait.Training.PhaseMapTraining.Learn(recordings);
                var gates = HeadGait.Training.GaitTraining.TrainGates(training);
                HeadGait.Training.GaitTraining.TrainThreshold(training, map, gates.Threshold).Save(Path.Combine(output, GaitModels.ThresholdFile));
                var template = HeadGait.Training.GaitTraining.TrainCorrelation(training, map, gates.Correlation);
                template.Save(Path.Combine(output, GaitModels.CorrelationFile));
                Debug.Log($"HeadGait: wrote THR and COR into {output} from {recordings.Count} recordings ({template.StepsUsed} steps). SVM and BLSTM train with `headgait train` (Python).");
                AssetDatabase.Refresh();
            }
            catch (System.Exception e) when (e is RecordingFormatException || e is IOException || e is System.InvalidOperationException)
            {
                EditorUtility.DisplayDialog("HeadGait", e.Message, "OK");
            }
        }

        /// <summary>The package's gait clips, as the Animator Controller's states play them.</summary>
        const string ClipFolder = "Packages/com.headgait.legmotion/Runtime/Animation/";

        /// <summary>The COR template whose phase map times the package's clips (as `headgait clips` uses it).</summary>
        const string PackageTemplate = "Packages/com.headgait.legmotion/Models/" + GaitModels.CorrelationFile;

        /// <summary>The package's locomotion controller and the mannequin's material, as the shipped prefabs use them.</summary>
        const string PackageController = ClipFolder + "HeadGait Legs.controller";
        const string PackageMaterial = "Packages/com.headgait.legmotion/Runtime/Materials/HeadGait Mannequin.mat";

        /// <summary>The phase map of the COR template the user picks, or of the package's when the picker was cancelled.</summary>
        static PhaseMap PickedPhaseMap(string template)
            => (string.IsNullOrEmpty(template)
                ? CorrelationTemplate.Parse(AssetDatabase.LoadAssetAtPath<TextAsset>(PackageTemplate)?.text ?? throw new IOException(PackageTemplate + " is missing; reinstall the package"), PackageTemplate)
                : CorrelationTemplate.Load(template)).PhaseMap;

        /// <summary>The package's gait clips by state, or null (after saying so) when one is missing.</summary>
        static System.Collections.Generic.Dictionary<LocomotionState, AnimationClip> PackageClips()
        {
            var clips = new System.Collections.Generic.Dictionary<LocomotionState, AnimationClip>();
            foreach (var state in GaitClips.All)
            {
                var clip = AssetDatabase.LoadAssetAtPath<AnimationClip>(ClipFolder + GaitClips.Name(state) + ".anim");
                if (clip == null)
                {
                    EditorUtility.DisplayDialog("HeadGait", $"The gait clip {ClipFolder}{GaitClips.Name(state)}.anim is missing; reinstall the package.", "OK");
                    return null;
                }
                clips[state] = clip;
            }
            return clips;
        }

        static T PackageAsset<T>(string path) where T : Object
        {
            var asset = AssetDatabase.LoadAssetAtPath<T>(path);
            if (asset == null) EditorUtility.DisplayDialog("HeadGait", $"{path} is missing; reinstall the package.", "OK");
            return asset;
        }

        [MenuItem("Tools/HeadGait/Create Animator Controller...")]
        static void CreateAnimatorController()
        {
            string path = EditorUtility.SaveFilePanelInProject("Create the HeadGait locomotion Animator Controller", "HeadGait Legs", "controller",
                "States, parameters and transitions as the package's HeadGait Legs.controller; its states play the package's gait clips.");
            if (string.IsNullOrEmpty(path)) return;
            var package = PackageClips();
            if (package == null) return;
            var clips = new System.Collections.Generic.Dictionary<LocomotionState, Motion>();
            foreach (var state in LocomotionController.States) clips[state] = package[state];
            LocomotionControllerBuilder.Create(path, clips);
            Debug.Log($"HeadGait: wrote {path}");
        }

        [MenuItem("Tools/HeadGait/Create Gait Clips and Animator Controller...")]
        static void CreateClipsAndController()
        {
            string template = EditorUtility.OpenFilePanel("COR template whose phase map times the clips (cancel: the package's)", Path.GetFullPath("Packages/com.headgait.legmotion/Models"), "txt");
            string path = EditorUtility.SaveFilePanelInProject("Create the HeadGait gait clips and locomotion Animator Controller", "HeadGait Legs", "controller",
                "The six gait clips are written beside the controller, timed by the COR template's phase map.");
            if (string.IsNullOrEmpty(path)) return;
            try
            {
                var map = PickedPhaseMap(template);
                var clips = GaitClipBuilder.Create(path.Substring(0, path.LastIndexOf('/')), map);
                LocomotionControllerBuilder.Create(path, clips);
                Debug.Log($"HeadGait: wrote {path} and its six gait clips beside it (right initial contact at stride {map.RightOffset:F4})");
            }
            catch (System.Exception e) when (e is IOException || e is System.FormatException)
            {
                EditorUtility.DisplayDialog("HeadGait", e.Message, "OK");
            }
        }

        [MenuItem("Tools/HeadGait/Create Humanoid Clips and Override Controller...")]
        static void CreateHumanoidClips()
        {
            string template = EditorUtility.OpenFilePanel("COR template whose phase map times the clips (cancel: the package's)", Path.GetFullPath("Packages/com.headgait.legmotion/Models"), "txt");
            string path = EditorUtility.SaveFilePanelInProject("Create the Humanoid gait clips and an Animator Override Controller", "HeadGait Legs Humanoid", "overrideController",
                "The six Humanoid clips are written into a Humanoid folder beside it; it plays the package's HeadGait Legs.controller with them, for your own Humanoid avatar.");
            if (string.IsNullOrEmpty(path)) return;
            var originals = PackageClips();
            var controller = PackageAsset<RuntimeAnimatorController>(PackageController);
            if (originals == null || controller == null) return;
            try
            {
                var map = PickedPhaseMap(template);
                string parent = path.Substring(0, path.LastIndexOf('/'));
                string folder = parent + "/Humanoid";
                if (!AssetDatabase.IsValidFolder(folder)) AssetDatabase.CreateFolder(parent, "Humanoid");
                var humanoid = HumanoidClipBuilder.Create(folder, map);
                HumanoidClipBuilder.CreateOverrideController(path, controller, originals, humanoid);
                Debug.Log($"HeadGait: wrote {path} and its six Humanoid clips in {folder} (right initial contact at stride {map.RightOffset:F4})");
            }
            catch (System.Exception e) when (e is IOException || e is System.FormatException)
            {
                EditorUtility.DisplayDialog("HeadGait", e.Message, "OK");
            }
        }

        [MenuItem("Tools/HeadGait/Create Prefabs...")]
        static void CreatePrefabs()
        {
            string path = EditorUtility.SaveFilePanelInProject("Create the HeadGait drop-in prefab and mannequin prefab", Mannequin.LegsPrefabRoot, "prefab",
                "The drop-in prefab (Gait Leg Animator, Head IMU Source, Follow Head, the mannequin as its avatar) is written here, the mannequin prefab beside it; both play the package's controller.");
            if (string.IsNullOrEmpty(path)) return;
            var controller = PackageAsset<RuntimeAnimatorController>(PackageController);
            var material = PackageAsset<Material>(PackageMaterial);
            var template = PackageAsset<TextAsset>(PackageTemplate);
            if (controller == null || material == null || template == null) return;
            string mannequin = path.Substring(0, path.LastIndexOf('/') + 1) + Mannequin.PrefabRoot + ".prefab";
            GaitPrefabBuilder.CreateLegs(path, controller, material, template);
            GaitPrefabBuilder.CreateMannequin(mannequin, controller, material);
            Debug.Log($"HeadGait: wrote {path} and {mannequin}");
        }

        static void Append(StringBuilder sb, ReplayResult r)
        {
            var m = r.ClassifierMetrics;
            var a = r.AnimatorMetrics;
            if (m == null)
            {
                sb.AppendLine($"{r.Classifier}: no ground truth; {r.Windows} windows, {r.MeanWindowMs:F3} ms/window");
                return;
            }
            sb.AppendLine($"{r.Classifier}: misclassification {m.MisclassificationRate:P1} (avatar {a.MisclassificationRate:P1}), MAE {m.Mae:F2}, RMSE {m.Rmse:F2}, " +
                          $"CEP50/95 {m.Cep50}/{m.Cep95}, delay {m.MeanDelayMs:F0} ms, {r.MeanWindowMs:F3} ms/window");
        }
    }
}
