using System.IO;

namespace HeadGait.Study
{
    /// <summary>
    /// Every file operation of the <see cref="StudyJournal"/> goes through here, so that tests can stand in a full disk or a
    /// crash at any write (a subclass whose streams fail or stop part-way). The default is the real file system.
    /// </summary>
    public class JournalFileAccess
    {
        public static JournalFileAccess Default { get; } = new JournalFileAccess();

        /// <summary>
        /// Opens without a write buffer (each line is one write): a line the disk refuses must fail at its write and leave
        /// nothing behind that a later flush or the close could still write after the journal said it was not saved.
        /// </summary>
        public virtual Stream Open(string path, FileMode mode, FileAccess access, FileShare share)
            => new FileStream(path, mode, access, share, 1, FileOptions.None);

        /// <summary>Pushes what was written through the operating system's caches onto the disk.</summary>
        public virtual void FlushToDisk(Stream stream)
        {
            if (stream is FileStream file) file.Flush(true);
            else stream.Flush();
        }

        /// <summary>Renames; fails when <paramref name="to"/> exists (a journal is never overwritten).</summary>
        public virtual void Move(string from, string to) => File.Move(from, to);

        public virtual void Delete(string path) => File.Delete(path);

        public virtual bool Exists(string path) => File.Exists(path);
    }
}
