// The test framework's [UnityTest] stand-in (UnityEngine.TestRunner.cs) ends the stand-ins' frame through FrameLoop, an
// internal of these UnityEngine stand-ins; the compile check builds it as its own assembly, as Unity ships it.
[assembly: System.Runtime.CompilerServices.InternalsVisibleTo("UnityEngine.TestRunner")]
// The UnityEditor stand-in saves prefabs through GameObject.CopyForAsset (Unity's engine modules grant UnityEditor their
// internals too).
[assembly: System.Runtime.CompilerServices.InternalsVisibleTo("UnityEditor")]
