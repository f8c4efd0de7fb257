using System;
using System.CommandLine;
using System.IO;
using HeadGait.Tooling;

namespace HeadGait.Cli
{
    /// <summary>headgait unity-meta: writes missing .meta files for the package and the project's Assets, or checks them.</summary>
    static class UnityMetaCommand
    {
        public static Command Build()
        {
            var check = new Option<bool>("--check") { Description = "only report missing, orphaned, malformed or duplicate .meta files (exit 1 if any)" };
            var command = new Command("unity-meta", "Writes a .meta (new GUID, the right importer) for every file and folder Unity imports that lacks one.") { check };
            command.SetAction(parse =>
            {
                string package = Path.GetDirectoryName(SamplePaths.FindModelsFolder() ?? throw new UsageException("package folder not found")) ?? ".";
                string assets = Path.Combine(package, "..", "..", "Assets");
                var roots = new[] { Path.GetFullPath(package), Path.GetFullPath(assets) };
                if (!parse.GetValue(check))
                    foreach (var root in roots)
                        foreach (var written in UnityMeta.WriteMissing(root)) Console.WriteLine($"wrote {written}");
                var problems = UnityMeta.Problems(roots);
                foreach (var p in problems) Console.WriteLine(p);
                return problems.Count == 0 ? 0 : 1;
            });
            return command;
        }
    }
}
