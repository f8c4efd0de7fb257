using System;

namespace HeadGait
{
    /// <summary>
    /// The windows a batch of samples completes, in order, with the stream restarts (gaps) between them, so that a learned
    /// classifier's evaluator scores them all in one call (one inference for Sentis) and the rest of the classifier then
    /// decides each window in order, as it would have one window at a time. Buffers grow to the largest batch and are
    /// reused. Used by <see cref="GaitPipeline.PushBatch"/>.
    /// </summary>
    public sealed class LearnedWindowBatch
    {
        readonly LearnedClassifier classifier;
        readonly int width, outputCount; // per reading
        double[] features = Array.Empty<double>(); // [row][time][channel]: each window's LearnedClassifier.RowsToScore readings
        double[] outputs = Array.Empty<double>();  // [row][output]
        Entry[] entries = new Entry[16];
        int entryCount, rowCount;
        bool evaluated;

        /// <summary>A window (its first row) or, with Row = -1, a restart of the stream at Time.</summary>
        struct Entry
        {
            public int Row;
            public double Time;
            public LearnedClassifier.WindowReading Reading;
        }

        public LearnedWindowBatch(LearnedClassifier classifier)
        {
            this.classifier = classifier ?? throw new ArgumentNullException(nameof(classifier));
            width = classifier.Features.Width;
            outputCount = classifier.OutputCount;
        }

        /// <summary>Windows and restarts queued, in order.</summary>
        public int Count => entryCount;

        /// <summary>Queues a window: its standardised features are copied now (the preprocessor reuses the window).</summary>
        public void AddWindow(SignalWindow window)
        {
            if (evaluated) throw new InvalidOperationException("Clear the batch before adding to it again.");
            var rows = classifier.StandardiseRows(window);
            int n = classifier.RowsToScore;
            if ((rowCount + n) * width > features.Length)
            {
                int capacity = Math.Max(16, 2 * (rowCount + n));
                Array.Resize(ref features, capacity * width);
                Array.Resize(ref outputs, capacity * outputCount);
            }
            Array.Copy(rows, 0, features, rowCount * width, n * width);
            Add(new Entry { Row = rowCount, Time = window.EndTime, Reading = classifier.Read(window) });
            rowCount += n;
        }

        /// <summary>Queues a restart of the stream (a gap or a clock jump) at <paramref name="time"/>, between the windows around it.</summary>
        public void AddRestart(double time)
        {
            if (evaluated) throw new InvalidOperationException("Clear the batch before adding to it again.");
            Add(new Entry { Row = -1, Time = time });
        }

        void Add(Entry e)
        {
            if (entryCount == entries.Length) Array.Resize(ref entries, entries.Length * 2);
            entries[entryCount++] = e;
        }

        /// <summary>Scores every queued window in one call of the classifier's evaluator (none when no window is queued).</summary>
        public void Evaluate()
        {
            if (rowCount > 0) classifier.Evaluator.Evaluate(features, rowCount, outputs);
            evaluated = true;
        }

        /// <summary>True when entry <paramref name="index"/> is a restart; <paramref name="time"/> is when.</summary>
        public bool IsRestart(int index, out double time)
        {
            var e = entries[index];
            time = e.Time;
            return e.Row < 0;
        }

        /// <summary>The prediction for window entry <paramref name="index"/>; call in order, after <see cref="Evaluate"/>.</summary>
        public GaitPrediction Classify(int index)
        {
            if (!evaluated) throw new InvalidOperationException("Evaluate the batch before classifying its windows.");
            var e = entries[index];
            if (e.Row < 0) throw new ArgumentException($"Entry {index} is a restart, not a window.", nameof(index));
            return classifier.ClassifyScoredAt(outputs, e.Row * outputCount, e.Reading);
        }

        public void Clear()
        {
            entryCount = 0;
            rowCount = 0;
            evaluated = false;
        }
    }
}
