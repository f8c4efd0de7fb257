using System;
using System.CommandLine;
using System.IO;
using HeadGait.Mocap;

namespace HeadGait.Cli
{
    public static class Program
    {
        public static int Main(string[] args)
        {
            var root = new RootCommand("headgait: gait reconstruction from a head-mounted accelerometer")
            {
                ReplayCommand.Build(),
                BenchmarkCommand.Build(),
                TrainCommand.Build(),
                FromBvhCommand.Build(),
                GenerateCommand.Build(),
                UnityMetaCommand.Build(),
                ClipsCommand.Build(),
                StudyCommand.Build(),
                CalibrateCommand.Build(),
                RealWorldCommand.Build(),
            };
            try
            {
                return root.Parse(args).Invoke(new InvocationConfiguration { EnableDefaultExceptionHandler = false });
            }
            catch (UsageException e)
            {
                Console.Error.WriteLine($"error: {e.Message}");
                return 2;
            }
            catch (Exception e) when (e is HeadGait.Study.StudyStorageException || e is RecordingFormatException || e is BvhFormatException || e is ModelFormatException || e is IOException
                                      || e is FormatException || e is InvalidOperationException || e is UnauthorizedAccessException)
            {
                Console.Error.WriteLine($"error: {e.Message}");
                return 1;
            }
        }
    }
}
