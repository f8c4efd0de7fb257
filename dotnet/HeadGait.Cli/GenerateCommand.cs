using System;
using System.CommandLine;
using System.IO;
using HeadGait.Synthetic;

namespace HeadGait.Cli
{
    /// <summary>headgait generate: rewrites the generated sample recordings bit for bit.</summary>
    static class GenerateCommand
    {
        public static Command Build()
        {
            var output = new Option<string>("--out") { Description = "folder (default: the package's Samples~/Recordings)" };
            var command = new Command("generate", "Regenerates the synthetic sample recordings.") { output };
            command.SetAction(parse =>
            {
                string root = parse.GetValue(output) ?? SamplePaths.FindRecordingsFolder() ?? throw new UsageException("no --out and no package folder found");
                foreach (var e in SampleLibrary.All)
                {
                    string dir = Path.Combine(root, e.Set);
                    Directory.CreateDirectory(dir);
                    string path = Path.Combine(dir, e.Name + ".csv");
                    AtomicFile.WriteAllText(path, SampleLibrary.ToCsv(e));
                    Console.WriteLine($"wrote {path}: {e.Description}");
                }
                return 0;
            });
            return command;
        }
    }
}
