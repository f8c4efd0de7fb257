using System;
using System.Globalization;
using HeadGait.Study;

namespace HeadGait.Tests.JournalChild
{
    /// <summary>
    /// hold FOLDER ID: opens the participant as the operator does, prints "opened" (or "refused" and the error) and holds
    /// it until standard input closes. answer FOLDER ID: opens it and saves answers a1, a2, ... printing "ack N" after each
    /// call returns (that is, once it is on disk), until the process is killed.
    /// </summary>
    static class Program
    {
        static int Main(string[] args)
        {
            if (args.Length != 3 || (args[0] != "hold" && args[0] != "answer"))
            {
                Console.Error.WriteLine("usage: hold|answer FOLDER ID");
                return 2;
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
