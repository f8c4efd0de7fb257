// Stand-in for UnityEngine.Camera, only what FollowHead uses. Signature from UnityCsReference
// Runtime/Export/Camera/Camera.bindings.cs (public sealed partial class Camera : Behaviour; static Camera main { get; }:
// the first enabled camera tagged MainCamera). There is no scene here, so there is no main camera.
namespace UnityEngine
{
    public sealed class Camera : Behaviour
    {
        public static Camera main => null;
    }
}
