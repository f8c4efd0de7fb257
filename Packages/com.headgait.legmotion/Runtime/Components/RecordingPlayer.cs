using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>
    /// Replays a recorded CSV (TextAsset) into a <see cref="GaitLegAnimator"/> in real time, so an avatar can be
    /// checked in the editor without a headset. Set the HeadImuSource (if any) to External meanwhile.
    /// </summary>
    [AddComponentMenu("HeadGait/Recording Player")]
    public sealed class RecordingPlayer : MonoBehaviour
    {
        [SerializeField] GaitLegAnimator target;
        [SerializeField] TextAsset recording;
        [SerializeField] bool loop = true;
        [SerializeField, Range(0.1f, 4f)] float speed = 1f;

        Recording data;
        int next;
        double clock;
        double offset;

        /// <summary>Ground truth of the row last played, when the recording has it.</summary>
        public RecordedSample LastRow { get; private set; }

        void OnEnable()
        {
            if (target == null) target = GetComponent<GaitLegAnimator>();
            if (recording == null) return;
            try
            {
                data = RecordingCsv.Parse(recording.text, recording.name);
            }
            catch (RecordingFormatException e)
            {
                Debug.LogError($"HeadGait: cannot play '{recording.name}': {e.Message}", this);
                data = null;
                return;
            }
            if (data.Warnings.Count > 0) Debug.LogWarning($"HeadGait: '{recording.name}': {data.Warnings.Count} row(s) skipped, first: {data.Warnings[0]}", this);
            Restart();
        }

        void Restart()
        {
            next = 0;
            clock = 0;
            offset = data.Samples.Count > 0 ? data.Samples[0].Imu.Time : 0;
        }

        void Update()
        {
            if (data == null || target == null || data.Samples.Count == 0) return;
            clock += Time.deltaTime * speed;
            while (next < data.Samples.Count && data.Samples[next].Imu.Time - offset <= clock)
            {
                var row = data.Samples[next++];
                LastRow = row;
                target.Push(row.Imu.Time, new Vector3((float)row.Imu.X, (float)row.Imu.Y, (float)row.Imu.Z));
            }
            if (next >= data.Samples.Count && loop)
            {
                target.Build();
                Restart();
            }
        }
    }
}
