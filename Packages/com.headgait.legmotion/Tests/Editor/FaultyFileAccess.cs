using System;
using System.Collections.Generic;
using System.IO;
using HeadGait.Study;

namespace HeadGait.Tests
{
    /// <summary>The process running the journal was killed at a write point (thrown where the kill happened; nothing after it runs).</summary>
    sealed class SimulatedCrash : Exception
    {
        public SimulatedCrash() : base("simulated crash") { }
    }

    /// <summary>
    /// The journal's file access with a full disk or a process kill at a chosen write point (every stream write, length
    /// change, flush to disk, rename and delete is one), standing in one process: <see cref="Kill"/> closes every handle it
    /// opened, as the operating system does for a dead process (its locks go with them). Part of the write that fails can
    /// be made to reach the file first, as a disk filling mid-line or a kill mid-write leaves it.
    /// </summary>
    sealed class FaultyFileAccess : JournalFileAccess
    {
        readonly List<Stream> handles = new List<Stream>();
        int faultAt = -1, keepBytes;
        bool crash, full, dead;

        /// <param name="syncToDisk">False skips the real fsync (campaigns: the journal's logic is under test, not the disk).</param>
        public FaultyFileAccess(bool syncToDisk = true) => SyncToDisk = syncToDisk;

        public bool SyncToDisk { get; }
        /// <summary>Write points passed so far.</summary>
        public int WritePoints { get; private set; }
        /// <summary>True once the planned fault has happened.</summary>
        public bool Faulted { get; private set; }

        /// <summary>The disk is full from the write point <paramref name="writes"/> from now: that write keeps <paramref name="keepBytes"/> bytes (at most) and fails, later ones fail outright.</summary>
        public void FillDiskAfter(int writes, int keepBytes)
        {
            faultAt = WritePoints + writes;
            this.keepBytes = keepBytes;
            crash = false;
        }

        /// <summary>The process is killed at the write point <paramref name="writes"/> from now, after <paramref name="keepBytes"/> bytes of it reached the file.</summary>
        public void CrashAfter(int writes, int keepBytes)
        {
            faultAt = WritePoints + writes;
            this.keepBytes = keepBytes;
            crash = true;
        }

        public void FreeSpace()
        {
            full = false;
            faultAt = -1;
        }

        /// <summary>The process dies: every handle it holds is closed; it runs nothing more.</summary>
        public void Kill()
        {
            dead = true;
            foreach (var h in handles) h.Dispose();
            handles.Clear();
        }

        /// <summary>Counts a write point; true when this one is to fail (after writing what <see cref="keepBytes"/> allows).</summary>
        bool Fails()
        {
            if (dead) throw new SimulatedCrash();
            int point = WritePoints++;
            if (point == faultAt)
            {
                Faulted = true;
                if (!crash) full = true;
                return true;
            }
            return full;
        }

        void Fail(bool first)
        {
            if (crash)
            {
                Kill();
                throw new SimulatedCrash();
            }
            throw new IOException("No space left on device" + (first ? "" : " (still full)"));
        }

        public override Stream Open(string path, FileMode mode, FileAccess access, FileShare share)
        {
            if (dead) throw new SimulatedCrash();
            var s = (FileStream)base.Open(path, mode, access, share);
            handles.Add(s);
            return new Faulty(s, this);
        }

        public override void FlushToDisk(Stream stream)
        {
            bool first = WritePoints == faultAt;
            if (Fails()) Fail(first);
            var inner = ((Faulty)stream).Inner;
            if (SyncToDisk) inner.Flush(true);
            else inner.Flush();
        }

        public override void Move(string from, string to)
        {
            bool first = WritePoints == faultAt;
            if (Fails()) Fail(first);
            base.Move(from, to);
        }

        public override void Delete(string path)
        {
            if (dead) throw new SimulatedCrash();
            int point = WritePoints++;
            if (point == faultAt && crash)
            {
                Faulted = true;
                Fail(true);
            }
            base.Delete(path); // deleting frees space: it works on a full disk
        }

        sealed class Faulty : Stream
        {
            readonly FaultyFileAccess owner;

            public Faulty(FileStream inner, FaultyFileAccess owner)
            {
                Inner = inner;
                this.owner = owner;
            }

            public FileStream Inner { get; }
            public override bool CanRead => Inner.CanRead;
            public override bool CanSeek => Inner.CanSeek;
            public override bool CanWrite => Inner.CanWrite;
            public override long Length => Alive().Length;

            public override long Position
            {
                get => Alive().Position;
                set => Alive().Position = value;
            }

            FileStream Alive()
            {
                if (owner.dead) throw new SimulatedCrash();
                return Inner;
            }

            public override void Flush() => Alive().Flush();
            public override int Read(byte[] buffer, int offset, int count) => Alive().Read(buffer, offset, count);
            public override long Seek(long offset, SeekOrigin origin) => Alive().Seek(offset, origin);

            public override void SetLength(long value)
            {
                bool first = owner.WritePoints == owner.faultAt;
                // Shortening a file frees space: it works on a full disk (but a kill can still come first).
                bool fails = owner.Fails();
                if (fails && (owner.crash || value > Inner.Length)) owner.Fail(first);
                Inner.SetLength(value);
            }

            public override void Write(byte[] buffer, int offset, int count)
            {
                bool first = owner.WritePoints == owner.faultAt;
                if (owner.Fails())
                {
                    int keep = first ? Math.Min(count, Math.Max(0, owner.keepBytes)) : 0;
                    Inner.Write(buffer, offset, keep);
                    Inner.Flush();
                    owner.Fail(first);
                }
                Inner.Write(buffer, offset, count);
            }

            protected override void Dispose(bool disposing)
            {
                if (disposing && !owner.dead)
                {
                    Inner.Dispose();
                    owner.handles.Remove(Inner);
                }
                base.Dispose(disposing);
            }
        }
    }
}
