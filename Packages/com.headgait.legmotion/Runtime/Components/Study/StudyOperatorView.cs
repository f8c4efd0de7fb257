using HeadGait.Study;
using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>
    /// The operator's screen on the desktop window (IMGUI, so it needs no assets and is not drawn in the headset):
    /// participant id entry, participant, step, condition order, what to do now, the controls Start / Next / Repeat
    /// trial / Abort, the SSQ as it is being answered, any error (a full or read-only disk) in a box of its own, and the data
    /// folder. A standalone headset does not show this view: the SSQ panel in the headset repeats errors and the folder.
    /// The keyboard rates the SSQ (see <see cref="StudyKeyboard"/>).
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("HeadGait/Study/Study Operator View")]
    public sealed class StudyOperatorView : MonoBehaviour
    {
        [SerializeField] StudyRunner runner;
        [Tooltip("Width of the operator panel in pixels.")]
        [SerializeField] float width = 460;

        string idField = "";
        string ageField = "";
        string genderField = "";

        void Awake()
        {
            if (runner == null) runner = GetComponent<StudyRunner>();
        }

        void OnGUI()
        {
            var e = Event.current;
            var op = runner != null ? runner.Operator : null;
            if (e != null && e.type == EventType.KeyDown && StudyKeyboard.Handle(e.keyCode, op)) e.Use();

            GUILayout.BeginArea(new Rect(10, 10, width, Screen.height - 20));
            if (runner == null || op == null)
            {
                GUILayout.Box("ERROR: " + (runner == null ? "no Study Runner is assigned to the operator view." : runner.SetupError));
                if (runner != null) GUILayout.Label("Data folder: " + runner.DataFolder);
                GUILayout.EndArea();
                return;
            }
            if (runner.SetupError != null) GUILayout.Box("SETUP: " + runner.SetupError);
            var screen = op.Screen();
            if (screen.Error != null) GUILayout.Box("ERROR: " + screen.Error);
            if (screen.Participant == null) DrawIdEntry(op);
            else DrawSession(op, screen);
            GUILayout.Label(screen.Instruction);
            if (screen.Notice != null) GUILayout.Label(screen.Notice);
            GUILayout.Label("Data folder: " + op.DataFolder);
            GUILayout.EndArea();
        }

        void DrawIdEntry(StudyOperator op)
        {
            GUILayout.BeginHorizontal();
            GUILayout.Label("Participant id", GUILayout.Width(100));
            idField = GUILayout.TextField(idField, ParticipantIds.MaxLength, GUILayout.Width(200));
            if (GUILayout.Button("Open", GUILayout.Width(80))) op.Open(idField);
            GUILayout.EndHorizontal();
        }

        void DrawSession(StudyOperator op, OperatorScreen screen)
        {
            GUILayout.Label("Participant: " + screen.Participant);
            GUILayout.Label(screen.Step);
            var order = "Order:";
            for (int i = 0; i < screen.ConditionOrder.Count; i++)
                order += i == screen.CurrentCondition ? $"  [{i + 1}. {screen.ConditionOrder[i]}]" : $"  {i + 1}. {screen.ConditionOrder[i]}";
            GUILayout.Label(order);

            if (op.Current.Value.Kind == StudyStepKind.Demographics) DrawDemographics(op);
            if (op.SsqOpen) DrawSsq(op.Ssq);

            GUILayout.BeginHorizontal();
            Control(op, OperatorCommand.Start, "Start");
            Control(op, OperatorCommand.Next, "Next");
            Control(op, OperatorCommand.RepeatTrial, "Repeat trial");
            Control(op, OperatorCommand.Abort, "Abort");
            GUILayout.EndHorizontal();
        }

        static void Control(StudyOperator op, OperatorCommand command, string label)
        {
            GUI.enabled = op.CanDo(command);
            if (GUILayout.Button(label, GUILayout.Width(100))) op.Do(command);
            GUI.enabled = true;
        }

        void DrawDemographics(StudyOperator op)
        {
            GUILayout.BeginHorizontal();
            GUILayout.Label("Age", GUILayout.Width(60));
            ageField = GUILayout.TextField(ageField, 3, GUILayout.Width(60));
            GUILayout.Label("Gender", GUILayout.Width(60));
            genderField = GUILayout.TextField(genderField, 32, GUILayout.Width(120));
            if (GUILayout.Button("Save", GUILayout.Width(60)) && op.SetDemographic("age", ageField.Trim())) op.SetDemographic("gender", genderField.Trim());
            GUILayout.EndHorizontal();
        }

        static void DrawSsq(SsqForm form)
        {
            for (int i = 0; i < SimulatorSicknessQuestionnaire.ItemCount; i++)
            {
                int? r = form.RatingOf(i);
                string mark = i == form.Focus ? "> " : "  ";
                GUILayout.Label($"{mark}{i + 1,2}. {SimulatorSicknessQuestionnaire.Label((SsqItem)i)}: {(r.HasValue ? $"{r} {SimulatorSicknessQuestionnaire.RatingLabel(r.Value)}" : "-")}");
            }
        }
    }
}
