using UnityEngine;
using UnityEngine.TestTools;

namespace HeadGait.Tests
{
    /// <summary>
    /// A Play Mode fixture that reads the package's own files (Models/, Samples~/) from disk: run in the editor only. A player
    /// (Test Runner's "Run on player", a headset) has no package folder, so there these fixtures are skipped, not failed.
    /// </summary>
    public sealed class NeedsPackageFilesAttribute : UnityPlatformAttribute
    {
        public NeedsPackageFilesAttribute() : base(RuntimePlatform.WindowsEditor, RuntimePlatform.OSXEditor, RuntimePlatform.LinuxEditor) { }
    }
}
