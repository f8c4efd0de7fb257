using System;
using System.Collections.Generic;
using System.CommandLine;
using System.IO;
using HeadGait.Mocap;

namespace HeadGait.Cli
{
    /// <summary>headgait from-bvh: motion capture to labelled head-IMU recordings.</summary>
    static class FromBvhCommand
    {
        public static Command Build()
        {
            var inputs = new Argument<string[]>("bvh") { Arity = ArgumentArity.OneOrMore, Description = "BVH files or folders of them" };
            var output = new Option<string>("--out") { Description = "folder for the recordings (CSV)", Required = true };
            var units = new Option<string>("--units") { Description = "file units: cm, m, mm, in or auto (from the leg length)", DefaultValueFactory = _ => "auto" };
            var up = new Option<string>("--up") { Description = "world up axis of the files: x, y, z or auto", DefaultValueFactory = _ => "auto" };
            var noNoise = new Option<bool>("--no-noise") { Description = "leave out the simulated sensor bias, noise and timestamp jitter" };
            var pose = new Option<string>("--pose") { Description = "write head-pose recordings (headgait-pose v1) at these frame rates instead, e.g. 72,90,120: the XR pose path's input, with tracking noise and frame-time jitter" };
            var seed = new Option<ulong>("--seed") { Description = "seed of the sensor errors (default: from each file's name)" };
            var joints = new Dictionary<string, Option<string>>();
            var command = new Command("from-bvh", "Converts BVH motion capture into head-IMU recordings with per-foot gait-phase labels.")
            {
                inputs, output, units, up, noNoise, seed, pose,
            };
            foreach (var role in MocapConverter.DefaultNames.Keys)
            {
                var o = new Option<string>("--" + role) { Description = $"name of the {role} joint (default: first of {string.Join(", ", MocapConverter.DefaultNames[role])})" };
                joints[role] = o;
                command.Options.Add(o);
            }
            command.SetAction(parse =>
            {
                var s = new MocapSettings
                {
                    Head = parse.GetValue(joints["head"]),
                    LeftFoot = parse.GetValue(joints["left-foot"]),
                    LeftToe = parse.GetValue(joints["left-toe"]),
                    RightFoot = parse.GetValue(joints["right-foot"]),
                    RightToe = parse.GetValue(joints["right-toe"]),
                    LeftHip = parse.GetValue(joints["left-hip"]),
                    RightHip = parse.GetValue(joints["right-hip"]),
                    MetresPerUnit = Units(parse.GetValue(units)),
                    UpAxis = Axis(parse.GetValue(up)),
                    Seed = parse.GetValue(seed),
                };
                if (parse.GetValue(noNoise)) s.BiasSd = s.NoiseSd = s.JitterSd = s.PositionNoiseSd = s.RotationNoiseDegrees = s.FrameJitterSd = 0;
                var rates = OptionValues.FrameRates(parse.GetValue(pose), "--pose", 10, 1000);
                string outDir = parse.GetValue(output);
                var files = Inputs.Expand(parse.GetValue(inputs), "*.bvh");
                int failed = 0;
                foreach (var f in files)
                {
                    try
                    {
                        var bvh = BvhFile.Load(f);
                        foreach (double rate in rates)
                        {
                            var poses = MocapConverter.ConvertPose(bvh, rate, s);
                            string posePath = Path.Combine(outDir, poses.Name + ".csv");
                            PoseCsv.Save(poses, posePath);
                            Console.WriteLine($"{posePath}: {poses.Rows.Count} poses at {rate:0} Hz");
                        }
                        if (rates.Count > 0) continue;
                        var rec = MocapConverter.Convert(bvh, s);
                        string path = Path.Combine(outDir, rec.Name + ".csv");
                        RecordingCsv.Save(rec, path);
                        int walking = 0;
                        foreach (var r in rec.Samples) if (r.Left != GaitPhase.Standing) walking++;
                        Console.WriteLine($"{path}: {rec.Samples.Count} samples ({rec.Duration:F1} s), walking {100.0 * walking / Math.Max(1, rec.Samples.Count):F0} %; joints {rec.Metadata["joints"]}");
                    }
                    catch (BvhFormatException e)
                    {
                        Console.Error.WriteLine($"error: {e.Message}");
                        failed++;
                    }
                }
                return failed == 0 ? 0 : 1;
            });
            return command;
        }

        static double Units(string u)
        {
            switch ((u ?? "auto").ToLowerInvariant())
            {
                case "auto": return 0;
                case "cm": return 0.01;
                case "m": return 1;
                case "mm": return 0.001;
                case "in": return 0.0254;
                default: throw new UsageException($"--units must be cm, m, mm, in or auto, not '{u}'");
            }
        }

        static int Axis(string a)
        {
            switch ((a ?? "auto").ToLowerInvariant())
            {
                case "auto": return -1;
                case "x": return 0;
                case "y": return 1;
                case "z": return 2;
                default: throw new UsageException($"--up must be x, y, z or auto, not '{a}'");
            }
        }
    }
}
