using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>
    /// Replays a recorded CSV (TextAsset) into a <see cref="GaitLegAnimator"/> in real time, so an avatar can be
    /// checked in the editor without a headset. Set the HeadImuSource (if any) to External meanwhile. Each enable and each
    /// loop starts the animator's stream over (see <see cref="RecordingPlayback"/>).
    /// </summary>
    [AddComponentMenu("HeadGait/Recording Player")]
    public sealed class RecordingPlayer : MonoBehaviour
    {
        [SerializeField] GaitLegAnimator target;
        [SerializeField] TextAsset recording;
        [SerializeField] bool loop = true;
        [SerializeField, Range(0.1f, 4f)] float speed = 1f;

        RecordingPlayback playback;

        /// <summary>Ground truth of the row last played, when the recording has it.</summary>
        public RecordedSample LastRow => playback != null ? playback.LastRow : default;

        void OnEnable()
        {
            if (target == null) target = GetComponent<GaitLegAnimator>();
            playback = null;
            if (recording == null) return;
            Recording data;
            try
            {
                data = RecordingCsv.Parse(recording.text, recording.name);
            }
            catch (RecordingFormatException e)
            {
                Debug.LogError($"HeadGait: cannot play '{recording.name}': {e.Message}", this);
                return;
            }
            if (data.Warnings.Count > 0) Debug.LogWarning($"HeadGait: '{recording.name}': {data.Warnings.Count} row(s) skipped, first: {data.Warnings[0]}", this);
            playback = new RecordingPlayback(data) { Loop = loop };
            playback.Restart(target != null ? target.Runner : null);
        }

        void Update()
        {
            if (playback == null || target == null) return;
            playback.Loop = loop;
            playback.Advance(Time.deltaTime * speed, target.Runner);
        }
    }
}
