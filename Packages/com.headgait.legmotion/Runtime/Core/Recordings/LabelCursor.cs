using System.Collections.Generic;

namespace HeadGait
{
    /// <summary>
    /// The labels in force at each window's end, for readers that take a recording's windows in order (training the
    /// walking gates, exporting the learned classifiers' windows): the last row at or before the time. Times must not
    /// go back; each row is passed once, so a whole recording costs one pass.
    /// </summary>
    public sealed class LabelCursor
    {
        readonly List<RecordedSample> rows;
        int row = -1;

        public LabelCursor(Recording recording)
        {
            rows = recording.Samples;
        }

        /// <summary>
        /// The row in force at <paramref name="time"/> (s, within 1e-9 of a row's timestamp counting as at it); false when
        /// the time comes before the first row or that row holds no labels.
        /// </summary>
        public bool TryLabelsAt(double time, out RecordedSample labelled)
        {
            while (row + 1 < rows.Count && rows[row + 1].Imu.Time <= time + 1e-9) row++;
            labelled = row >= 0 ? rows[row] : default;
            return row >= 0 && labelled.HasTruth;
        }
    }
}
