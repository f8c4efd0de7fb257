using HeadGait.Study;
using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>
    /// The operator's keys for the SSQ while it is open: 0-3 (top row or keypad) rate the focused item, Up/Down move
    /// the focus, Return saves the questionnaire (Next). Read from IMGUI key events, which arrive whichever input
    /// handling (Input Manager or Input System) the project uses.
    /// </summary>
    public static class StudyKeyboard
    {
        /// <summary>Applies a key to the operator's session; false when the key means nothing now (so the event is left to others).</summary>
        public static bool Handle(KeyCode key, StudyOperator op)
        {
            if (op == null || !op.SsqOpen) return false;
            int rating = RatingOf(key);
            if (rating >= 0)
            {
                op.Ssq.RateFocused(rating);
                return true;
            }
            switch (key)
            {
                case KeyCode.UpArrow:
                    op.Ssq.MoveFocus(-1);
                    return true;
                case KeyCode.DownArrow:
                    op.Ssq.MoveFocus(1);
                    return true;
                case KeyCode.Return:
                case KeyCode.KeypadEnter:
                    op.Do(OperatorCommand.Next);
                    return true;
                default:
                    return false;
            }
        }

        /// <summary>The SSQ rating a key gives (0-3), or -1.</summary>
        public static int RatingOf(KeyCode key)
        {
            if (key >= KeyCode.Alpha0 && key <= KeyCode.Alpha3) return key - KeyCode.Alpha0;
            if (key >= KeyCode.Keypad0 && key <= KeyCode.Keypad3) return key - KeyCode.Keypad0;
            return -1;
        }
    }
}
