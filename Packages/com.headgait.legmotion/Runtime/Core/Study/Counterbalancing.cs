using System;
using System.Collections.Generic;

namespace HeadGait.Study
{
    /// <summary>
    /// Condition orders from a Williams design (a balanced Latin square): every condition comes at every position equally
    /// often and directly follows every other condition equally often, so order and first-order carry-over effects balance
    /// out over a full set of participants. n rows for an even number of conditions, 2n (the square and its mirror) for an odd.
    /// </summary>
    public static class Counterbalancing
    {
        /// <summary>The design's rows: each an order of the condition indices 0..n-1.</summary>
        public static int[][] WilliamsRows(int conditions)
        {
            if (conditions < 1 || conditions > 26) throw new ArgumentException("Counterbalancing needs 1 to 26 conditions.", nameof(conditions));
            int n = conditions;
            // First row: 0, 1, n-1, 2, n-2, 3, ...; every further row adds one to each entry (mod n).
            var first = new int[n];
            for (int i = 0, low = 1, high = n - 1; i < n; i++)
            {
                if (i == 0) first[i] = 0;
                else if (i % 2 == 1) first[i] = low++;
                else first[i] = high--;
            }
            var rows = new List<int[]>();
            for (int r = 0; r < n; r++)
            {
                var row = new int[n];
                for (int i = 0; i < n; i++) row[i] = (first[i] + r) % n;
                rows.Add(row);
            }
            if (n % 2 == 1 && n > 1)
            {
                for (int r = 0; r < n; r++)
                {
                    var mirror = (int[])rows[r].Clone();
                    Array.Reverse(mirror);
                    rows.Add(mirror);
                }
            }
            return rows.ToArray();
        }

        /// <summary>
        /// The row a participant gets: participants numbered 1, 2, 3, ... (the number at the end of the id, as in "P07")
        /// go through the rows in turn, so any full set of consecutive numbers is balanced; an id without a number gets a
        /// row from a stable hash of the id. The same id always gets the same row.
        /// </summary>
        public static int RowFor(string participantId, int rows)
        {
            if (rows < 1) throw new ArgumentException("At least one row.", nameof(rows));
            int end = participantId.Length, start = end;
            while (start > 0 && char.IsDigit(participantId[start - 1])) start--;
            if (start < end && end - start <= 9) return (int)((long.Parse(participantId.Substring(start, end - start)) + rows - 1) % rows);
            return (int)(Synthetic.DeterministicRandom.SeedFrom(participantId) % (ulong)rows);
        }

        /// <summary>The condition order (indices into the conditions) of a participant.</summary>
        public static int[] OrderFor(string participantId, int conditions)
        {
            var rows = WilliamsRows(conditions);
            return (int[])rows[RowFor(participantId, rows.Length)].Clone();
        }
    }
}
