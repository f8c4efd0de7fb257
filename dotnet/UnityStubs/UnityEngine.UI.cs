// Stand-ins for the uGUI (com.unity.ugui) members the study sample's SSQ panel uses. Signatures checked against the
// uGUI package sources (Runtime/UI/Core/Graphic.cs: color; MaskableGraphic.cs; Image.cs; Text.cs: text, font,
// fontSize, alignment; Selectable.cs: targetGraphic, interactable; Button.cs: onClick, Button.ButtonClickedEvent;
// Runtime/EventSystem/EventSystem.cs: EventSystem.current; Runtime/EventSystem/UIBehaviour.cs;
// Runtime/EventSystem/Raycasters/BaseRaycaster.cs; Runtime/EventSystem/InputModules/BaseInputModule.cs). UnityEvent is
// UnityEngine's own (UnityEngine.Events.cs).
// Only what the sample calls; nothing is drawn or clicked here.
namespace UnityEngine.EventSystems
{
    public abstract class UIBehaviour : MonoBehaviour { }

    public class EventSystem : UIBehaviour
    {
        public static EventSystem current { get; set; }
    }

    public abstract class BaseRaycaster : UIBehaviour { }

    public abstract class BaseInputModule : UIBehaviour { }
}

namespace UnityEngine.UI
{
    using UnityEngine.EventSystems;

    public abstract class Graphic : UIBehaviour
    {
        public virtual Color color { get; set; }
    }

    public abstract class MaskableGraphic : Graphic { }

    public class Image : MaskableGraphic { }

    public class Text : MaskableGraphic
    {
        public virtual string text { get; set; }
        public Font font { get; set; }
        public int fontSize { get; set; }
        public TextAnchor alignment { get; set; }
    }

    public class Selectable : UIBehaviour
    {
        public Graphic targetGraphic { get; set; }
        public bool interactable { get; set; }
    }

    public class Button : Selectable
    {
        public class ButtonClickedEvent : Events.UnityEvent { }

        public ButtonClickedEvent onClick { get; set; } = new ButtonClickedEvent();
    }
}
