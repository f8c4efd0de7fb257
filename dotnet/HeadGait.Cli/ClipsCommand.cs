using System;
using System.CommandLine;
using System.IO;
using HeadGait.Tooling;

namespace HeadGait.Cli
{
    /// <summary>headgait clips: generates the gait clips, Animator Controller, mannequin, drop-in prefab and sample scene from the core.</summary>
    static class ClipsCommand
    {
        public static Command Build()
        {
            var template = new Option<string>("--template") { Description = "COR template whose phase map times the clips (default: the package's Models/cor_template.txt)" };
            var picture = new Option<bool>("--picture") { Description = "also draw the clips as stick figures to Documentation~/images/gait-clips.svg and .png (rsvg-convert)" };
            var command = new Command("clips", "Writes the Unity gait clips (.anim), controller, mannequin and drop-in prefabs and the Legs sample scene from the normative gait table and the phase map.") { template, picture };
            command.SetAction(parse =>
            {
                string models = SamplePaths.FindModelsFolder() ?? throw new UsageException("package folder not found");
                string package = Path.GetDirectoryName(models);
                string path = parse.GetValue(template) ?? Path.Combine(models, GaitModels.CorrelationFile);
                if (!File.Exists(path)) throw new UsageException($"--template: no such file: {path}");
                var map = CorrelationTemplate.Load(path).PhaseMap;
                foreach (var written in GaitAssetFiles.WriteAll(package, map)) Console.WriteLine($"wrote {written}");
                Console.WriteLine($"phase map from {path}: right initial contact at stride {map.RightOffset:F4}");
                if (parse.GetValue(picture)) WritePicture(package, new GaitClips(map));
                return 0;
            });
            return command;
        }

        static void WritePicture(string package, GaitClips clips)
        {
            string folder = Path.Combine(package, "Documentation~", "images");
            Directory.CreateDirectory(folder);
            SvgPicture.Write(GaitStickFigureSvg.Write(clips, GaitStickFigureSvg.DefaultRows(clips)), Path.Combine(folder, "gait-clips.png"));
        }
    }
}
