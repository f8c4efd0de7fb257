// Stand-ins for the XR Interaction Toolkit (com.unity.xr.interaction.toolkit 2.x/3.x) types the study sample adds so
// that XR controllers can press the SSQ panel's uGUI buttons. Checked against the package sources:
// Runtime/UI/TrackedDeviceGraphicRaycaster.cs (public class TrackedDeviceGraphicRaycaster : BaseRaycaster, namespace
// UnityEngine.XR.Interaction.Toolkit.UI) and Runtime/UI/XRUIInputModule.cs (public class XRUIInputModule :
// UIInputModule, UIInputModule : BaseInputModule, same namespace).
using UnityEngine.EventSystems;

namespace UnityEngine.XR.Interaction.Toolkit.UI
{
    public class TrackedDeviceGraphicRaycaster : BaseRaycaster { }

    public abstract class UIInputModule : BaseInputModule { }

    public class XRUIInputModule : UIInputModule { }
}
