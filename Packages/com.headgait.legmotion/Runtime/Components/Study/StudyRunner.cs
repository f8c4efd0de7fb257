using System;
using System.Collections.Generic;
using System.IO;
using HeadGait.Study;
using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>
    /// Runs the simulator-sickness study in the scene: holds the <see cref="StudyOperator"/> (participant, steps,
    /// SSQ form, journal on disk) that the operator view and the VR SSQ panel act on, and shows the avatar of the
    /// condition being walked through the <see cref="AvatarConditionSwitcher"/>.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("HeadGait/Study/Study Runner")]
    public sealed class StudyRunner : MonoBehaviour
    {
        [Tooltip("Where participants' journals are written. Empty: 'HeadGait Study' in Application.persistentDataPath (on a Quest or other Android headset /storage/emulated/0/Android/data/<package name>/files; on Windows %userprofile%/AppData/LocalLow/<company>/<product>).")]
        [SerializeField] string dataFolder = "";

        [Header("Study settings (a resumed participant keeps the settings it was started with)")]
        [SerializeField] List<string> conditions = new List<string> { StudyConfig.NoAvatar, StudyConfig.BlockAvatar, StudyConfig.HumanoidAvatar };
        [Tooltip("Length of the path from Start over Turn to End (m).")]
        [SerializeField] float pathLengthMeters = 16;
        [Tooltip("Rest between conditions (s).")]
        [SerializeField] float restSeconds = 120;
        [Tooltip("Classifier animating the humanoid, recorded with each participant (the paper: cor).")]
        [SerializeField] string humanoidClassifier = "cor";

        [SerializeField] AvatarConditionSwitcher avatars;

        /// <summary>Null when the settings are unusable; <see cref="SetupError"/> says why.</summary>
        public StudyOperator Operator { get; private set; }

        /// <summary>A problem with the scene or settings, for the operator screen; null when all is well.</summary>
        public string SetupError { get; private set; }

        /// <summary>
        /// 'HeadGait Study' in Application.persistentDataPath: the one folder a standalone headset lets the application write
        /// and keeps across updates (a desktop's Documents does not exist there); `adb pull` copies it off an Android headset.
        /// </summary>
        public static string DefaultDataFolder => Path.Combine(Application.persistentDataPath, "HeadGait Study");

        /// <summary>Where this runner's journals are written; shown in the operator view and the headset's panel.</summary>
        public string DataFolder { get; private set; }

        void Awake()
        {
            var config = new StudyConfig
            {
                Conditions = new List<string>(conditions),
                PathLengthMeters = pathLengthMeters,
                RestSeconds = restSeconds,
                HumanoidClassifier = humanoidClassifier,
            };
            DataFolder = string.IsNullOrWhiteSpace(dataFolder) ? DefaultDataFolder : dataFolder;
            try
            {
                Operator = new StudyOperator(DataFolder, config);
            }
            catch (ArgumentException e)
            {
                SetupError = $"Study settings on '{name}': {e.Message}";
                return;
            }
            if (avatars == null) SetupError = $"'{name}' has no Avatar Condition Switcher; the avatar conditions cannot be shown.";
            else
            {
                var missing = avatars.Missing(config.Conditions);
                if (missing.Count > 0) SetupError = $"The Avatar Condition Switcher has no entry for: {string.Join(", ", missing)}.";
            }
        }

        void Update()
        {
            if (avatars != null && Operator != null) avatars.Show(Operator.ActiveCondition);
        }

        // Releases the open participant's lock when the scene or play mode ends (the editor process lives on).
        void OnDestroy() => Operator?.Dispose();
    }
}
