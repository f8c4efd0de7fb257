using System;
using System.IO;
using NUnit.Framework;

namespace HeadGait.Tests
{
    public class AtomicFileTests
    {
        string dir;

        [SetUp]
        public void SetUp()
        {
            dir = Path.Combine(Path.GetTempPath(), "headgait-atomic-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
        }

        [TearDown]
        public void TearDown() => Directory.Delete(dir, true);

        [Test]
        public void AWriteThatFailsHalfwayLeavesTheEarlierFileAndNoTemporary()
        {
            string path = Path.Combine(dir, "cor_template.txt");
            AtomicFile.WriteAllText(path, "version 1");
            // A full disk surfaces as an IOException in the middle of writing.
            var e = Assert.Throws<IOException>(() => AtomicFile.WriteText(path, w =>
            {
                w.Write("version 2, half");
                w.Flush();
                throw new IOException("No space left on device");
            }));
            Assert.That(e.Message, Does.Contain(path).And.Contain("No space left on device"));
            Assert.That(File.ReadAllText(path), Is.EqualTo("version 1"));
            Assert.That(Directory.GetFiles(dir), Is.EqualTo(new[] { path }));
        }

        [Test]
        public void ASuccessfulWriteReplacesTheFile()
        {
            string path = Path.Combine(dir, "sub", "walk.csv");
            AtomicFile.WriteAllText(path, "a");
            AtomicFile.WriteAllBytes(path, new byte[] { 98 });
            Assert.That(File.ReadAllText(path), Is.EqualTo("b"));
        }
    }
}
