using HeadGait.Study;
using UnityEngine;
using UnityEngine.EventSystems;
using UnityEngine.UI;
using UnityEngine.XR.Interaction.Toolkit.UI;

namespace HeadGait.Unity
{
    /// <summary>
    /// The SSQ in the headset: a world-space uGUI panel, one symptom at a time (bigger targets for a controller ray
    /// than a 16-row grid), with the four ratings, previous/next item and Done. XR controllers press it through the XR
    /// Interaction Toolkit (a TrackedDeviceGraphicRaycaster on the panel's canvas, an XRUIInputModule on the
    /// EventSystem; both are added when missing). It edits the same <see cref="SsqForm"/> as the operator's keyboard,
    /// and shows itself while the current step is an SSQ or the study has an error (a standalone headset shows no operator
    /// view, so its errors and the data folder must appear here). Built from code, so the sample needs no UI assets.
    /// </summary>
    [AddComponentMenu("HeadGait/Study/SSQ Panel (XR)")]
    public sealed class SsqPanel : MonoBehaviour
    {
        [SerializeField] StudyRunner runner;
        [Tooltip("Panel size in canvas units; the canvas is scaled so that 1000 units are 1 m.")]
        [SerializeField] Vector2 size = new Vector2(900, 520);

        static readonly Color Background = new Color(0.12f, 0.14f, 0.18f, 0.95f);
        static readonly Color Idle = new Color(0.85f, 0.87f, 0.9f, 1f);
        static readonly Color Chosen = new Color(0.35f, 0.75f, 0.45f, 1f);

        GameObject canvasObject;
        Text title, status, folder;
        readonly Image[] ratingImages = new Image[SimulatorSicknessQuestionnaire.MaxRating + 1];
        Button done;
        Font font;
        int shownVersion = -1;
        string shownProblem;

        void Start()
        {
            if (runner == null)
            {
                Debug.LogError("HeadGait SSQ panel: no Study Runner assigned.", this);
                return;
            }
            font = Resources.GetBuiltinResource<Font>(BuiltinFontName);
            Build();
            if (EventSystem.current == null) new GameObject("EventSystem (XR UI)", typeof(EventSystem), typeof(XRUIInputModule));
        }

#if UNITY_2022_2_OR_NEWER
        const string BuiltinFontName = "LegacyRuntime.ttf";
#else
        const string BuiltinFontName = "Arial.ttf";
#endif

        void Build()
        {
            canvasObject = new GameObject("SSQ Canvas", typeof(RectTransform));
            var rect = (RectTransform)canvasObject.transform;
            rect.SetParent(GetComponent<Transform>(), false);
            rect.sizeDelta = size;
            rect.localScale = new Vector3(0.001f, 0.001f, 0.001f);
            canvasObject.AddComponent<Canvas>().renderMode = RenderMode.WorldSpace;
            canvasObject.AddComponent<TrackedDeviceGraphicRaycaster>();
            canvasObject.AddComponent<Image>().color = Background;

            title = Label("Item", new Vector2(0, 190), new Vector2(860, 90), 44);
            string[] ratingText = { "0 None", "1 Slight", "2 Moderate", "3 Severe" };
            for (int r = 0; r <= SimulatorSicknessQuestionnaire.MaxRating; r++)
            {
                int rating = r;
                var b = ButtonAt(ratingText[r], new Vector2(-330 + 220 * r, 60), new Vector2(200, 110), () => Form?.RateFocused(rating));
                ratingImages[r] = (Image)b.targetGraphic;
            }
            ButtonAt("< Previous", new Vector2(-300, -80), new Vector2(240, 80), () => Form?.MoveFocus(-1));
            ButtonAt("Next >", new Vector2(300, -80), new Vector2(240, 80), () => Form?.MoveFocus(1));
            done = ButtonAt("Done", new Vector2(0, -80), new Vector2(240, 80), () => runner.Operator?.Do(OperatorCommand.Next));
            status = Label("", new Vector2(0, -180), new Vector2(860, 70), 30);
            folder = Label("Data folder: " + runner.DataFolder, new Vector2(0, -235), new Vector2(860, 40), 20);
        }

        SsqForm Form => runner != null && runner.Operator != null && runner.Operator.SsqOpen ? runner.Operator.Ssq : null;

        void Update()
        {
            if (canvasObject == null) return;
            var form = Form;
            string problem = runner.SetupError ?? runner.Operator?.Error;
            canvasObject.SetActive(form != null || problem != null);
            if ((form == null || form.Version == shownVersion) && problem == shownProblem) return;
            shownProblem = problem;
            if (form == null)
            {
                title.text = "Study stopped: ask the operator";
                status.text = "ERROR: " + problem;
                return;
            }
            shownVersion = form.Version;
            int item = form.Focus;
            title.text = $"{item + 1} of {SimulatorSicknessQuestionnaire.ItemCount}: {SimulatorSicknessQuestionnaire.Label((SsqItem)item)}";
            int? rating = form.RatingOf(item);
            for (int r = 0; r < ratingImages.Length; r++) ratingImages[r].color = rating == r ? Chosen : Idle;
            done.interactable = form.IsComplete;
            status.text = problem != null ? "ERROR: " + problem
                : form.IsComplete ? "All rated. Press Done." : $"{form.AnsweredCount} of {SimulatorSicknessQuestionnaire.ItemCount} rated";
        }

        Text Label(string text, Vector2 position, Vector2 extent, int fontSize)
        {
            var go = new GameObject("Label", typeof(RectTransform));
            Place(go, position, extent);
            var t = go.AddComponent<Text>();
            t.text = text;
            t.font = font;
            t.fontSize = fontSize;
            t.alignment = TextAnchor.MiddleCenter;
            t.color = Idle;
            return t;
        }

        Button ButtonAt(string text, Vector2 position, Vector2 extent, UnityEngine.Events.UnityAction onClick)
        {
            var go = new GameObject(text, typeof(RectTransform));
            Place(go, position, extent);
            var image = go.AddComponent<Image>();
            image.color = Idle;
            var button = go.AddComponent<Button>();
            button.targetGraphic = image;
            button.onClick.AddListener(onClick);
            var label = Label(text, new Vector2(0, 0), extent, 34);
            ((RectTransform)label.GetComponent<Transform>()).SetParent(go.transform, false);
            label.color = Background;
            return button;
        }

        void Place(GameObject go, Vector2 position, Vector2 extent)
        {
            var rect = (RectTransform)go.transform;
            rect.SetParent(canvasObject.transform, false);
            rect.anchoredPosition = position;
            rect.sizeDelta = extent;
        }
    }
}
