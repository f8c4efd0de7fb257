using System;
using System.Globalization;
using HeadGait.Study;

namespace HeadGait.Tests.JournalChild
{
    /// <summary>
    /// hold FOLDER ID: opens the participant as the operator does, prints "opened" (or "refused" and the error) and holds
    /// it until standard input closes. answer FOLDER ID: opens it and saves answers a1, a2, ... printing "ack N" after each
    /// call returns (that is, once it is on disk), until the process is killed. record FOLDER ID: opens the participant's
    /// lock file without .NET's whole-file lock (as a runtime that checks sharing only within its own process lets a second process do) and
    /// asks for the record lock on its first byte, printing "locked" or "refused" and the error.
    /// </summary>
    static class Program
    {
        static int Main(string[] args)
        {
            if (args.Length != 3 || (args[0] != "hold" && args[0] != "answer" && args[0] != "record"))
            {
                Console.Error.WriteLine("usage: hold|answer|record FOLDER ID");
                return 2;
            }
            if (args[0] == "record")
            {
                // .NET refuses a second process's open by a whole-file lock (flock); Unity's runtimes on Unix players do not.
                AppContext.SetSwitch("System.IO.DisableFileLocking", true);
                string path = System.IO.Path.Combine(args[1], args[2] + StudyJournal.LockExtension);
                using (var file = new System.IO.FileStream(path, System.IO.FileMode.OpenOrCreate, System.IO.FileAccess.ReadWrite, System.IO.FileShare.ReadWrite | System.IO.FileShare.Delete))
                {
                    try
                    {
                        file.Lock(0, 1);
                    }
                    catch (System.IO.IOException e)
                    {
                        Console.WriteLine("refused\t" + e.Message);
                        return 1;
                    }
                    Console.WriteLine("locked");
                    return 0;
                }
            }
            var op = new StudyOperator(args[1], new StudyConfig());
            if (!op.Open(args[2]))
            {
                Console.WriteLine("refused\t" + op.Error);
                return 1;
            }
            Console.WriteLine("opened");
            Console.Out.Flush();
            if (args[0] == "hold")
            {
                Console.In.ReadToEnd();
                op.Dispose();
                return 0;
            }
            for (int n = 1; ; n++)
            {
                op.Session.Answer("a" + n.ToString(CultureInfo.InvariantCulture), "value " + n.ToString(CultureInfo.InvariantCulture));
                Console.WriteLine("ack " + n.ToString(CultureInfo.InvariantCulture));
                Console.Out.Flush();
            }
        }
    }
}
