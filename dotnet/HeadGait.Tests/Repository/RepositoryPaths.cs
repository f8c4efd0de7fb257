using System.IO;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>Where the repository tests read the package and the repository from: found from the test's folder upwards.</summary>
    static class RepositoryPaths
    {
        /// <summary>The package folder (Packages/com.headgait.legmotion).</summary>
        public static string Package => Path.GetDirectoryName(SamplePaths.FindModelsFolder(TestContext.CurrentContext.TestDirectory));

        /// <summary>The repository root, two folders above the package.</summary>
        public static string Root => Path.GetFullPath(Path.Combine(Package, "..", ".."));
    }
}
