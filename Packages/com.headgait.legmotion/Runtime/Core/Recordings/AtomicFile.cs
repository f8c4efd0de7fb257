using System;
using System.IO;
using System.Text;

namespace HeadGait
{
    /// <summary>
    /// Writes a whole file or nothing: the content goes to a temporary file beside the target, which then replaces it.
    /// A full disk or a crash mid-write leaves the previous file as it was.
    /// </summary>
    public static class AtomicFile
    {
        public static void Write(string path, Action<Stream> write)
        {
            string full = Path.GetFullPath(path);
            string dir = Path.GetDirectoryName(full);
            if (!string.IsNullOrEmpty(dir)) Directory.CreateDirectory(dir);
            string tmp = full + ".tmp";
            try
            {
                using (var stream = new FileStream(tmp, FileMode.Create, FileAccess.Write, FileShare.None))
                {
                    write(stream);
                    stream.Flush(true);
                }
                if (File.Exists(full)) File.Replace(tmp, full, null);
                else File.Move(tmp, full);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                TryDelete(tmp);
                throw new IOException($"{full}: could not be written ({e.Message}); any earlier version is unchanged", e);
            }
            catch
            {
                TryDelete(tmp);
                throw;
            }
        }

        public static void WriteText(string path, Action<TextWriter> write) => Write(path, s =>
        {
            using (var w = new StreamWriter(s, new UTF8Encoding(false), 65536, leaveOpen: true))
            {
                w.NewLine = "\n";
                write(w);
            }
        });

        public static void WriteAllText(string path, string text) => WriteText(path, w => w.Write(text));

        public static void WriteAllBytes(string path, byte[] bytes) => Write(path, s => s.Write(bytes, 0, bytes.Length));

        static void TryDelete(string path)
        {
            try
            {
                if (File.Exists(path)) File.Delete(path);
            }
            catch (IOException)
            {
            }
            catch (UnauthorizedAccessException)
            {
            }
        }
    }
}
