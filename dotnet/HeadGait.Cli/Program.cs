using System;
using System.CommandLine;
using System.CommandLine.Parsing;
using System.IO;
using HeadGait.Mocap;

namespace HeadGait.Cli
{
    public static class Program
    {
        /// <summary>Options whose value may be empty (an empty list of extra arguments).</summary>
        static readonly string[] MayBeEmpty = { "--python-args" };

        /// <summary>The option (or "an argument") given an empty or blank value, or null: no path, list or number is empty.</summary>
        static string EmptyValue(ParseResult parsed)
        {
            string option = null;
            foreach (var token in parsed.Tokens)
            {
                if (token.Type == TokenType.Option)
                {
                    option = token.Value;
                    continue;
                }
                if (token.Type == TokenType.Argument && token.Value.Trim().Length == 0 && Array.IndexOf(MayBeEmpty, option) < 0)
                    return option ?? "an argument";
                if (token.Type != TokenType.Argument) option = null;
            }
            return null;
        }

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
                AnimatorCheckCommand.Build(),
                CalibrateCommand.Build(),
                RealWorldCommand.Build(),
            };
            // The exit-code rule: 0 success, 1 a runtime or data error (a file that cannot be read, nothing to do), 2 usage (an
            // unknown command or option, a missing or bad option value). Never a stack trace.
            try
            {
                var parsed = root.Parse(args);
                if (parsed.Errors.Count > 0)
                {
                    foreach (var error in parsed.Errors) Console.Error.WriteLine($"error: {error.Message}");
                    Console.Error.WriteLine("(see --help)");
                    return 2;
                }
                string empty = EmptyValue(parsed);
                if (empty != null)
                {
                    Console.Error.WriteLine($"error: {empty} is empty");
                    return 2;
                }
                return parsed.Invoke(new InvocationConfiguration { EnableDefaultExceptionHandler = false });
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
            catch (Exception e)
            {
                // Anything else is a defect or an input no check foresaw: one line, still no stack trace.
                Console.Error.WriteLine($"error: {e.GetType().Name}: {e.Message}");
                return 1;
            }
        }
    }
}
