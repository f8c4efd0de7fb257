using System;
using System.Diagnostics;
using System.IO;

namespace HeadGait.Cli
{
    /// <summary>Writes an SVG picture and, where rsvg-convert (Debian's librsvg2-bin) is installed, its PNG.</summary>
    static class SvgPicture
    {
        public static void Write(string svg, string pngPath)
        {
            string svgPath = Path.ChangeExtension(pngPath, ".svg");
            AtomicFile.WriteAllText(svgPath, svg);
            try
            {
                var p = Process.Start(new ProcessStartInfo("rsvg-convert", $"-o \"{pngPath}\" \"{svgPath}\"") { UseShellExecute = false, RedirectStandardError = true });
                string err = p.StandardError.ReadToEnd();
                p.WaitForExit();
                if (p.ExitCode != 0) throw new InvalidOperationException($"{pngPath}: rsvg-convert failed: {err}");
                Console.WriteLine($"wrote {pngPath} (and {svgPath})");
            }
            catch (System.ComponentModel.Win32Exception)
            {
                Console.WriteLine($"wrote {svgPath}; for a PNG install rsvg-convert (apt-get install librsvg2-bin)");
            }
        }
    }
}
