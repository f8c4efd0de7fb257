// Stand-ins for the IMGUI API the study's operator view uses (Runtime/Components/Study). Signatures checked against
// UnityCsReference: Modules/IMGUI/GUILayout.cs (GUILayout is a class with static members, not a static class),
// Modules/IMGUI/GUILayoutOption.cs, Modules/IMGUI/GUI.cs and GUI.bindings.cs (GUI.enabled), Modules/IMGUI/Event.cs
// and Event.bindings.cs (Event.current, type, keyCode, Use), Modules/IMGUI/EventEnums.cs (EventType),
// Runtime/Export/Input/KeyCode.cs (KeyCode values), Runtime/Export/Math/Rect.cs and Runtime/Export/Screen/Screen.bindings.cs.
// Only what the package calls; drawing does nothing here.
namespace UnityEngine
{
    public sealed class GUILayoutOption { }

    public class GUILayout
    {
        public static void Label(string text, params GUILayoutOption[] options) { }
        public static void Box(string text, params GUILayoutOption[] options) { }
        public static bool Button(string text, params GUILayoutOption[] options) => false;
        public static string TextField(string text, int maxLength, params GUILayoutOption[] options) => text;
        public static void BeginArea(Rect screenRect) { }
        public static void EndArea() { }
        public static void BeginHorizontal(params GUILayoutOption[] options) { }
        public static void EndHorizontal() { }
        public static void Space(float pixels) { }
        public static GUILayoutOption Width(float width) => new GUILayoutOption();
    }

    public class GUI
    {
        public static bool enabled { get; set; } = true;
    }

    public enum EventType
    {
        MouseDown = 0, MouseUp = 1, MouseMove = 2, MouseDrag = 3, KeyDown = 4, KeyUp = 5, ScrollWheel = 6, Repaint = 7, Layout = 8,
    }

    public sealed class Event
    {
        public static Event current { get; set; }
        public EventType type { get; set; }
        public KeyCode keyCode { get; set; }
        public void Use() { }
    }

    public enum KeyCode
    {
        None = 0, Return = 13,
        Alpha0 = 48, Alpha1 = 49, Alpha2 = 50, Alpha3 = 51,
        Keypad0 = 256, Keypad1 = 257, Keypad2 = 258, Keypad3 = 259, KeypadEnter = 271,
        UpArrow = 273, DownArrow = 274,
    }

    public struct Rect
    {
        public Rect(float x, float y, float width, float height)
        {
            this.x = x;
            this.y = y;
            this.width = width;
            this.height = height;
        }

        public float x { get; set; }
        public float y { get; set; }
        public float width { get; set; }
        public float height { get; set; }
    }
}
