using System;
using System.IO;
using System.Threading.Tasks;
using HeadGait.Calibration;
using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>
    /// The wearer's calibration walk: at start-up applies the wearer's saved profile to a <see cref="GaitLegAnimator"/> (none:
    /// the shipped models); on <see cref="StartWalk"/> records the head samples the animator receives and, when two tracked
    /// devices are assigned (controllers strapped above the ankles, e.g. driven by a TrackedPoseDriver: their local position
    /// is the tracking-space position), their positions; after <see cref="walkSeconds"/> (or <see cref="FinishWalk"/>) fits
    /// the profile on a worker thread, saves it and applies it. The prompt goes to an optional TextMesh in the headset and to
    /// an on-screen box for the editor or a desktop (<see cref="showOnScreen"/>). <see cref="ResetWearer"/> deletes the profile.
    /// </summary>
    [AddComponentMenu("HeadGait/Wearer Calibration")]
    public sealed class WearerCalibration : MonoBehaviour
    {
        [SerializeField] GaitLegAnimator legs;
        [Tooltip("Who wears the headset; each wearer has their own profile.")]
        [SerializeField] string wearer = "wearer";
        [Tooltip("Folder of the profiles; empty: 'HeadGait Profiles' under Application.persistentDataPath.")]
        [SerializeField] string profileFolder = "";
        [Tooltip("Tracked device strapped above the left ankle (optional; without both ankles the walk is fitted self-supervised).")]
        [SerializeField] Transform leftAnkle;
        [SerializeField] Transform rightAnkle;
        [SerializeField] float walkSeconds = 60;
        [Tooltip("In-headset prompt: a small world-space TextMesh in front of the wearer (e.g. a child of the camera); optional.")]
        [SerializeField] TextMesh prompt;
        [Tooltip("Also show the prompt and Start / Finish / Reset buttons on screen (editor, desktop).")]
        [SerializeField] bool showOnScreen = true;

        CalibrationWalk walk;
        Task<WearerProfile> fitting;
        string note;

        /// <summary>The walk in progress or last done (null before the first).</summary>
        public CalibrationWalk Walk => walk;

        public string Wearer
        {
            get => wearer;
            set => wearer = value;
        }

        /// <summary>Where the profiles are kept.</summary>
        public WearerProfiles Profiles => new WearerProfiles(string.IsNullOrEmpty(profileFolder) ? Path.Combine(Application.persistentDataPath, "HeadGait Profiles") : profileFolder);

        /// <summary>What the wearer is told now.</summary>
        public string PromptText => walk != null ? walk.Prompt(Now) : note ?? new CalibrationWalk().Prompt(Now);

        static double Now => HeadClock.Now;

        void Awake()
        {
            if (legs == null) legs = GetComponent<GaitLegAnimator>();
        }

        void Start() => ApplySavedProfile();

        void OnEnable()
        {
            if (legs != null) legs.SamplePushed += OnSample;
        }

        void OnDisable()
        {
            if (legs != null) legs.SamplePushed -= OnSample;
        }

        /// <summary>Applies the wearer's saved profile, or the shipped models when there is none or it is unusable (said in the log).</summary>
        public void ApplySavedProfile()
        {
            if (legs == null) return;
            var shipped = legs.ReadModels(out _);
            Profiles.ModelsFor(wearer, shipped, out var profile, out note);
            if (note != null) Debug.Log($"HeadGait: {note}", this);
            legs.ApplyProfile(profile);
        }

        public void StartWalk()
        {
            if (fitting != null) return;
            walk = new CalibrationWalk(Math.Max(CalibrationWalk.MinSeconds, walkSeconds));
            walk.Begin(Now);
        }

        /// <summary>Ends the walk now and fits what it recorded.</summary>
        public void FinishWalk()
        {
            if (walk == null || walk.State != CalibrationWalk.Stage.Walking) return;
            var session = walk.End(wearer);
            if (session == null) return;
            var shipped = legs.ReadModels(out string error);
            if (error != null) Debug.LogWarning($"HeadGait: {error}", this);
            string id = wearer;
            fitting = Task.Run(() => session.Fit(shipped, id));
        }

        /// <summary>Deletes the wearer's profile and goes back to the shipped models.</summary>
        public void ResetWearer()
        {
            try
            {
                Profiles.Reset(wearer);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is ArgumentException)
            {
                note = $"Calibration for '{wearer}' not reset: {e.Message}";
                Debug.LogWarning($"HeadGait: {note}", this);
                return;
            }
            walk = null;
            legs?.ApplyProfile(null);
            note = $"Calibration for '{wearer}' reset: the legs use their usual settings.";
        }

        void OnSample(ImuSample sample) => walk?.AddHead(sample);

        /// <summary>
        /// Both ankle devices' positions (tracking space, m) at <paramref name="time"/> on the head samples' clock
        /// (<see cref="HeadClock.Now"/> for a pose read now), for
        /// devices read elsewhere (Input System actions, a recorded session); assigned ankle transforms are read every frame.
        /// </summary>
        public void AddAnklePoses(double time, Vector3 left, Vector3 right) => walk?.AddAnkles(time, left.x, left.y, left.z, right.x, right.y, right.z);

        /// <summary>The fit in progress (null when none): it finishes on a worker thread and is collected in Update.</summary>
        public Task<WearerProfile> Fitting => fitting;

        void Update()
        {
            if (walk != null && walk.State == CalibrationWalk.Stage.Walking)
            {
                if (leftAnkle != null && rightAnkle != null)
                {
                    AddAnklePoses(Now, leftAnkle.localPosition, rightAnkle.localPosition);
                }
                if (walk.IsDue(Now)) FinishWalk();
            }
            if (fitting != null && fitting.IsCompleted) Collect();
            if (prompt != null) prompt.text = PromptText;
        }

        void Collect()
        {
            var task = fitting;
            fitting = null;
            if (task.IsFaulted)
            {
                var e = task.Exception?.GetBaseException();
                walk.Fail(e?.Message ?? "the fit failed");
                Debug.LogWarning($"HeadGait: calibration walk not used: {walk.Outcome}", this);
                return;
            }
            try
            {
                Profiles.Save(task.Result);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is FormatException)
            {
                walk.Fail($"the profile could not be saved ({e.Message})");
                Debug.LogError($"HeadGait: {walk.Outcome}", this);
                return;
            }
            walk.Finish(task.Result);
            legs.ApplyProfile(task.Result);
        }

        void OnGUI()
        {
            if (!showOnScreen) return;
            GUILayout.BeginArea(new Rect(10, 10, 420, 160));
            GUILayout.Box(PromptText);
            GUILayout.BeginHorizontal();
            bool busy = fitting != null || (walk != null && walk.State == CalibrationWalk.Stage.Walking);
            if (!busy && GUILayout.Button("Start calibration walk")) StartWalk();
            if (walk != null && walk.State == CalibrationWalk.Stage.Walking && GUILayout.Button("Finish")) FinishWalk();
            if (!busy && GUILayout.Button("Reset wearer")) ResetWearer();
            GUILayout.EndHorizontal();
            GUILayout.EndArea();
        }
    }
}
