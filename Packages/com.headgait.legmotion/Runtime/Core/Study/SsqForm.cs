using System;
using System.Collections.Generic;

namespace HeadGait.Study
{
    /// <summary>
    /// The SSQ being filled in: which of the 16 items are rated, and which item has the focus (the one a keyboard digit
    /// rates). The VR panel and the operator's keyboard edit the same form; nothing is saved until the operator
    /// submits it to the <see cref="StudySession"/>.
    /// </summary>
    public sealed class SsqForm
    {
        const int Unanswered = -1;
        readonly int[] ratings = new int[SimulatorSicknessQuestionnaire.ItemCount];

        public SsqForm() => Clear();

        /// <summary>The item a keyboard rating goes to (0..15, <see cref="SsqItem"/> order).</summary>
        public int Focus { get; private set; }

        /// <summary>Counts every change, so a view can redraw only when something changed.</summary>
        public int Version { get; private set; }

        public int AnsweredCount
        {
            get
            {
                int n = 0;
                foreach (int r in ratings) if (r != Unanswered) n++;
                return n;
            }
        }

        public bool IsComplete => AnsweredCount == ratings.Length;

        /// <summary>The rating of an item, or null while unanswered.</summary>
        public int? RatingOf(int item)
        {
            CheckItem(item);
            return ratings[item] == Unanswered ? (int?)null : ratings[item];
        }

        /// <summary>Rates an item and moves the focus to the next unanswered item after it (or keeps it when all are answered).</summary>
        public void Rate(int item, int rating)
        {
            CheckItem(item);
            if (rating < 0 || rating > SimulatorSicknessQuestionnaire.MaxRating)
                throw new ArgumentOutOfRangeException(nameof(rating), $"SSQ ratings are 0 (none) to {SimulatorSicknessQuestionnaire.MaxRating} (severe); got {rating}.");
            ratings[item] = rating;
            Focus = item;
            for (int i = 1; i < ratings.Length; i++)
            {
                int next = (item + i) % ratings.Length;
                if (ratings[next] == Unanswered)
                {
                    Focus = next;
                    break;
                }
            }
            Version++;
        }

        public void RateFocused(int rating) => Rate(Focus, rating);

        /// <summary>Moves the focus up (negative) or down (positive), stopping at the first and last item.</summary>
        public void MoveFocus(int delta)
        {
            Focus = Math.Max(0, Math.Min(ratings.Length - 1, Focus + delta));
            Version++;
        }

        /// <summary>The 16 ratings; throws <see cref="InvalidOperationException"/> naming the first unanswered item.</summary>
        public int[] Ratings()
        {
            for (int i = 0; i < ratings.Length; i++)
                if (ratings[i] == Unanswered)
                    throw new InvalidOperationException($"SSQ item {i + 1} '{SimulatorSicknessQuestionnaire.Label((SsqItem)i)}' is not rated yet ({AnsweredCount} of {ratings.Length} rated).");
            return (int[])ratings.Clone();
        }

        /// <summary>Fills the form with saved ratings (a resumed SSQ step shows what was saved); the focus goes to the first item.</summary>
        public void Load(IReadOnlyList<int> saved)
        {
            SimulatorSicknessQuestionnaire.Score(saved);
            for (int i = 0; i < ratings.Length; i++) ratings[i] = saved[i];
            Focus = 0;
            Version++;
        }

        public void Clear()
        {
            for (int i = 0; i < ratings.Length; i++) ratings[i] = Unanswered;
            Focus = 0;
            Version++;
        }

        static void CheckItem(int item)
        {
            if (item < 0 || item >= SimulatorSicknessQuestionnaire.ItemCount)
                throw new ArgumentOutOfRangeException(nameof(item), $"SSQ items are 0 to {SimulatorSicknessQuestionnaire.ItemCount - 1}; got {item}.");
        }
    }
}
