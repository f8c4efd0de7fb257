using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Threading;
using System.Threading.Tasks;
using HeadGait.Study;
using HeadGait.Synthetic;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>
    /// A seeded campaign against the study journal as a hostile world and a careless operator would run it: a kill at every
    /// write point of a whole session (with none, some or all of the write on disk), a full disk at every write point, two
    /// operators opening one id at once, the journal cut at random lengths and single bits flipped. It prints and asserts
    /// the counts that matter: acknowledged answers lost, answers changed without a warning, ids blocked, journals
    /// unreadable (all 0). HEADGAIT_LONG_CAMPAIGN=1 runs it at ten times the size.
    /// </summary>
    public class StudyJournalCampaignTests
    {
        static readonly int Scale = Environment.GetEnvironmentVariable("HEADGAIT_LONG_CAMPAIGN") == "1" ? 10 : 1;
        const string Id = "P07";
        string folder;
        int run;

        [SetUp]
        public void MakeFolder() => folder = Path.Combine(Path.GetTempPath(), "headgait-campaign-" + Guid.NewGuid().ToString("N"));

        [TearDown]
        public void RemoveFolder()
        {
            if (Directory.Exists(folder)) Directory.Delete(folder, true);
        }

        string NewFolder() => Path.Combine(folder, "run" + run++);

        static void Report(string what, params (string name, int count)[] counts)
        {
            string line = $"study journal campaign, {what} (x{Scale}): " + string.Join(", ", counts.Select(c => $"{c.name} {c.count}"));
            TestContext.Progress.WriteLine(line);
            TestContext.Out.WriteLine(line);
        }

        /// <summary>What the operator was told is saved: an answer once its call returned true, a step once Next did.</summary>
        sealed class Acknowledged
        {
            public readonly Dictionary<(int step, string key), string> Answers = new Dictionary<(int, string), string>();
            public readonly HashSet<int> Done = new HashSet<int>();
        }

        static int[] SsqFor(int step) => Enumerable.Range(0, SimulatorSicknessQuestionnaire.ItemCount).Select(i => (step * 5 + i * 3 + i / 5) % 4).ToArray();

        /// <summary>One operator action toward the end of the session, as the operator view would give it; true when it was saved.</summary>
        static bool StepOnce(StudyOperator op, Acknowledged acks)
        {
            var step = op.Current.Value;
            bool ok;
            switch (step.Kind)
            {
                case StudyStepKind.Demographics:
                    var given = op.Session.AnswersOf(step.Index);
                    foreach (var (key, value) in new[] { ("age", "31"), ("gender", "female") })
                    {
                        if (given.ContainsKey(key)) continue;
                        ok = op.SetDemographic(key, value);
                        if (ok) acks.Answers[(step.Index, key)] = value;
                        return ok;
                    }
                    break;
                case StudyStepKind.BaselineWalk:
                case StudyStepKind.Trial:
                    if (!op.Walking) return op.Do(OperatorCommand.Start);
                    break;
                default:
                    if (step.IsSsq && !op.Ssq.IsComplete)
                        foreach (int r in SsqFor(step.Index)) op.Ssq.RateFocused(r);
                    break;
            }
            ok = op.Do(OperatorCommand.Next);
            if (ok)
            {
                if (step.IsSsq) acks.Answers[(step.Index, "ssq")] = string.Join(",", op.Session.SsqOf(step.Index) ?? SsqFor(step.Index));
                acks.Done.Add(step.Index);
            }
            return ok;
        }

        /// <summary>Compares what is on disk with what was acknowledged: (lost, changed) answers and steps.</summary>
        static (int lost, int changed) Check(StudySession saved, Acknowledged acks)
        {
            int lost = 0, changed = 0;
            foreach (var a in acks.Answers)
            {
                if (a.Key.key == "ssq")
                {
                    var all = saved.SsqAnswersOf(a.Key.step);
                    if (all.Count == 0) lost++;
                    else if (all.Any(v => v != a.Value)) changed++;
                    continue;
                }
                if (!saved.AnswersOf(a.Key.step).TryGetValue(a.Key.key, out var v)) lost++;
                else if (v != a.Value) changed++;
            }
            foreach (int d in acks.Done)
                if (!saved.IsComplete(d)) lost++;
            return (lost, changed);
        }

        static bool Clean(StudySession s) => s.Damage.Count == 0 && !s.RecoveredTornLine;

        /// <summary>A finished session read back: (lost, changed, unreadable) against what was acknowledged; unreadable also when it is not clean, not done or holds an SSQ twice.</summary>
        static (int lost, int changed, int unreadable) CheckFinished(string where, Acknowledged acks, string context)
        {
            try
            {
                using (var final = StudySession.Resume(where, Id, readOnly: true))
                {
                    var (lost, changed) = Check(final, acks);
                    bool whole = Clean(final) && final.Current.Kind == StudyStepKind.Done && final.Steps.Where(s => s.IsSsq).All(s => final.SsqAnswersOf(s.Index).Count == 1);
                    return (lost, changed, whole ? 0 : 1);
                }
            }
            catch (StudyStorageException e)
            {
                TestContext.Out.WriteLine($"{context}: {e.Message}");
                return (0, 0, 1);
            }
        }

        [Test]
        public void KillsAtEveryWritePointLoseNoAcknowledgedAnswer()
        {
            int lost = 0, changed = 0, blocked = 0, unreadable = 0, kills = 0, answersBeforeKills = 0;
            var config = new StudyConfig();
            var random = new DeterministicRandom(34);
            for (int point = 0; ; point++)
            {
                bool reachedEnd = false;
                // None, one byte, part and all of the write on disk when the process dies (more random parts in the long run).
                var keeps = new List<int> { 0, 1, 12, int.MaxValue };
                for (int i = 0; i < 4 * (Scale - 1); i++) keeps.Add(1 + (int)(random.NextDouble() * 120));
                foreach (int keep in keeps)
                {
                    string where = NewFolder();
                    var files = new FaultyFileAccess(syncToDisk: false);
                    files.CrashAfter(point, keep);
                    var acks = new Acknowledged();
                    var op = new StudyOperator(where, config, files);
                    try
                    {
                        if (!op.Open(Id)) blocked++;
                        else
                            for (int guard = 0; guard < 200 && op.Current.Value.Kind != StudyStepKind.Done; guard++)
                                if (!StepOnce(op, acks)) Assert.Fail($"write point {point}: a step failed without a fault: {op.Error}");
                    }
                    catch (SimulatedCrash)
                    {
                    }
                    if (!files.Faulted)
                    {
                        reachedEnd = true;
                        break;
                    }
                    kills++;
                    answersBeforeKills += acks.Answers.Count;
                    // A new process opens the id again and finishes the session.
                    var restarted = new StudyOperator(where, config, new FaultyFileAccess(syncToDisk: false));
                    if (!restarted.Open(Id))
                    {
                        TestContext.Out.WriteLine($"write point {point}, {keep} bytes kept: {restarted.Error}");
                        blocked++;
                        continue;
                    }
                    var (l, c) = Check(restarted.Session, acks);
                    lost += l;
                    changed += c;
                    for (int guard = 0; guard < 200 && restarted.Current.Value.Kind != StudyStepKind.Done; guard++)
                        if (!StepOnce(restarted, acks)) Assert.Fail($"write point {point}: after the restart: {restarted.Error}");
                    restarted.Dispose();
                    var (fl, fc, fu) = CheckFinished(where, acks, $"write point {point}");
                    lost += fl;
                    changed += fc;
                    unreadable += fu;
                }
                if (reachedEnd) break;
            }
            Report("kills at every write point", ("kills", kills), ("answers acknowledged before a kill", answersBeforeKills), ("acknowledged answers lost", lost),
                ("answers changed without a warning", changed), ("ids blocked", blocked), ("journals unreadable", unreadable));
            Assert.That(kills, Is.GreaterThan(100));
            Assert.That((lost, changed, blocked, unreadable), Is.EqualTo((0, 0, 0, 0)));
        }

        [Test]
        public void AFullDiskAtEveryWritePointLeavesAReadableJournalAndTheRetryLands()
        {
            int lost = 0, changed = 0, blocked = 0, unreadable = 0, failures = 0;
            var config = new StudyConfig();
            var random = new DeterministicRandom(35);
            for (int point = 0; ; point++)
            {
                bool reachedEnd = false;
                var keeps = new List<int> { 0, 9 };
                for (int i = 0; i < 2 * (Scale - 1); i++) keeps.Add((int)(random.NextDouble() * 120));
                foreach (int keep in keeps)
                {
                    string where = NewFolder();
                    var files = new FaultyFileAccess(syncToDisk: false);
                    files.FillDiskAfter(point, keep);
                    var acks = new Acknowledged();
                    var op = new StudyOperator(where, config, files);
                    bool stuck = false;
                    for (int guard = 0; guard < 300; guard++)
                    {
                        bool ok = op.Session == null ? op.Open(Id) : StepOnce(op, acks);
                        if (op.Session != null && op.Current.Value.Kind == StudyStepKind.Done) break;
                        if (ok) continue;
                        if (!files.Faulted)
                        {
                            stuck = true;
                            TestContext.Out.WriteLine($"write point {point}: failed without a fault: {op.Error}");
                            break;
                        }
                        if (!(op.Error ?? "").Contains(Id))
                        {
                            TestContext.Out.WriteLine($"write point {point}: an error that does not name the participant: {op.Error}");
                            stuck = true;
                            break;
                        }
                        // The operator frees space and gives the same command again.
                        failures++;
                        files.FreeSpace();
                    }
                    if (!files.Faulted)
                    {
                        reachedEnd = true;
                        op.Dispose();
                        break;
                    }
                    if (stuck || op.Session == null)
                    {
                        blocked++;
                        continue;
                    }
                    op.Dispose();
                    var (l, c, u) = CheckFinished(where, acks, $"write point {point}");
                    lost += l;
                    changed += c;
                    unreadable += u;
                    foreach (var f in Directory.GetFiles(where))
                        if (new FileInfo(f).Length == 0 && f.EndsWith(StudyJournal.Extension, StringComparison.Ordinal)) unreadable++;
                }
                if (reachedEnd) break;
            }
            Report("full disk at every write point", ("failed writes retried", failures), ("acknowledged answers lost", lost), ("answers changed without a warning", changed),
                ("ids blocked", blocked), ("journals unreadable", unreadable));
            Assert.That(failures, Is.GreaterThan(50));
            Assert.That((lost, changed, blocked, unreadable), Is.EqualTo((0, 0, 0, 0)));
        }

        [Test]
        public void TwoOperatorsOpeningOneIdAtOnceNeverBothWrite()
        {
            int rounds = 20 * Scale, bothWrote = 0, blocked = 0, unreadable = 0, refused = 0, holders = 0;
            var config = new StudyConfig();
            string where = NewFolder();
            var acks = new Acknowledged();
            for (int round = 0; round < rounds; round++)
            {
                using (var barrier = new Barrier(2))
                {
                    Func<(bool opened, string error)> contender = () =>
                    {
                        var op = new StudyOperator(where, config);
                        barrier.SignalAndWait();
                        if (!op.Open(Id)) return (false, op.Error);
                        if (Interlocked.Increment(ref holders) > 1) Interlocked.Increment(ref bothWrote);
                        for (int i = 0; i < 3 && op.Current.Value.Kind != StudyStepKind.Done; i++)
                            lock (acks)
                                StepOnce(op, acks);
                        Interlocked.Decrement(ref holders);
                        op.Dispose();
                        return (true, null);
                    };
                    var a = Task.Run(contender);
                    var b = Task.Run(contender);
                    foreach (var r in new[] { a.Result, b.Result })
                    {
                        if (r.opened) continue;
                        if (r.error != null && r.error.Contains("in use")) refused++;
                        else
                        {
                            TestContext.Out.WriteLine($"round {round}: {r.error}");
                            blocked++;
                        }
                    }
                }
                try
                {
                    using (var s = StudySession.Resume(where, Id, readOnly: true))
                    {
                        var journal = StudyJournal.Open(where, Id, forWriting: false);
                        var seq = journal.Entries.Select(e => e.Sequence).ToList();
                        if (!Clean(s) || seq.Distinct().Count() != seq.Count || Check(s, acks) != (0, 0)) unreadable++;
                    }
                }
                catch (StudyStorageException e)
                {
                    TestContext.Out.WriteLine($"round {round}: {e.Message}");
                    unreadable++;
                }
            }
            Report("two operators opening one id at once", ("rounds", rounds), ("second opens refused as in use", refused), ("both writing", bothWrote),
                ("ids blocked", blocked), ("journals unreadable", unreadable));
            Assert.That((bothWrote, blocked, unreadable), Is.EqualTo((0, 0, 0)));
        }

        /// <summary>A finished participant's journal (checksummed), and the summary values it gives.</summary>
        (byte[] bytes, Dictionary<string, string> summary) Reference()
        {
            string where = NewFolder();
            var op = new StudyOperator(where, new StudyConfig(), new FaultyFileAccess(syncToDisk: false));
            Assert.That(op.Open(Id), Is.True, op.Error);
            var acks = new Acknowledged();
            while (op.Current.Value.Kind != StudyStepKind.Done) Assert.That(StepOnce(op, acks), Is.True, op.Error);
            op.Dispose();
            var results = StudyResults.Load(where);
            Assert.That(results.Problems, Is.Empty);
            return (File.ReadAllBytes(Path.Combine(where, Id + StudyJournal.Extension)), Summary(results));
        }

        static Dictionary<string, string> Summary(StudyResults results)
        {
            var d = new Dictionary<string, string>();
            foreach (var p in results.Participants)
            {
                string S(SsqScores s) => $"{s.RawNausea}/{s.RawOculomotor}/{s.RawDisorientation}";
                if (p.PreExposure.HasValue) d[p.Participant + " pre"] = S(p.PreExposure.Value);
                if (p.Baseline.HasValue) d[p.Participant + " baseline"] = S(p.Baseline.Value);
                foreach (var c in p.Conditions) d[p.Participant + " " + c.Key] = S(c.Value) + " at " + p.Position[c.Key];
            }
            return d;
        }

        /// <summary>Loads a damaged copy of the journal; counts values changed (or gone) with no problem naming the file.</summary>
        static (bool changedSilently, bool missingSilently, bool warned) Judge(string where, Dictionary<string, string> reference)
        {
            var results = StudyResults.Load(where);
            bool warned = results.Problems.Any(p => p.Contains(Id + StudyJournal.Extension) || p.Contains(Id));
            var now = Summary(results);
            bool changed = now.Any(kv => !reference.TryGetValue(kv.Key, out var v) || v != kv.Value);
            bool missing = reference.Keys.Any(k => !now.ContainsKey(k));
            return (changed && !warned, missing && !warned, warned);
        }

        [Test]
        public void TruncationsNeverChangeAValueSilentlyNorBlockTheId()
        {
            var (bytes, reference) = Reference();
            var random = new DeterministicRandom(36);
            int cuts = 150 * Scale, changed = 0, atLineEnd = 0, warned = 0, blocked = 0, unreadable = 0;
            for (int i = 0; i < cuts; i++)
            {
                int cut = (int)(random.NextDouble() * bytes.Length);
                string where = NewFolder();
                Directory.CreateDirectory(where);
                File.WriteAllBytes(Path.Combine(where, Id + StudyJournal.Extension), bytes.Take(cut).ToArray());
                var (c, m, w) = Judge(where, reference);
                if (c) changed++;
                if (m) atLineEnd++;
                if (w) warned++;
                // The operator opens the id again and finishes it.
                var op = new StudyOperator(where, new StudyConfig(), new FaultyFileAccess(syncToDisk: false));
                if (!op.Open(Id))
                {
                    TestContext.Out.WriteLine($"cut at {cut}: {op.Error}");
                    blocked++;
                    continue;
                }
                var acks = new Acknowledged();
                for (int guard = 0; guard < 200 && op.Current.Value.Kind != StudyStepKind.Done; guard++)
                    if (!StepOnce(op, acks)) break;
                op.Dispose();
                try
                {
                    using (var s = StudySession.Resume(where, Id, readOnly: true))
                        if (!Clean(s) || s.Current.Kind != StudyStepKind.Done) unreadable++;
                }
                catch (StudyStorageException e)
                {
                    TestContext.Out.WriteLine($"cut at {cut}: {e.Message}");
                    unreadable++;
                }
            }
            // A cut exactly at a line end leaves a shorter journal that reads like a session that stopped there: nothing to warn of.
            Report("truncations", ("cuts", cuts), ("warned", warned), ("shortened at a line end (no trace)", atLineEnd), ("answers changed without a warning", changed),
                ("ids blocked", blocked), ("journals unreadable", unreadable));
            Assert.That((changed, blocked, unreadable), Is.EqualTo((0, 0, 0)));
        }

        [Test]
        public void SingleBitFlipsNeverChangeTheSummarySilently()
        {
            var (bytes, reference) = Reference();
            var random = new DeterministicRandom(37);
            int flips = 400 * Scale, changed = 0, missing = 0, warned = 0, notWarned = 0;
            string where = NewFolder();
            Directory.CreateDirectory(where);
            string path = Path.Combine(where, Id + StudyJournal.Extension);
            for (int i = 0; i < flips; i++)
            {
                var copy = (byte[])bytes.Clone();
                int at = (int)(random.NextDouble() * copy.Length);
                copy[at] ^= (byte)(1 << (int)(random.NextDouble() * 8));
                File.WriteAllBytes(path, copy);
                var (c, m, w) = Judge(where, reference);
                if (c) changed++;
                if (m) missing++;
                if (w) warned++;
                else notWarned++;
            }
            Report("single-bit flips", ("flips", flips), ("warned", warned), ("not warned", notWarned),
                ("answers changed without a warning", changed), ("answers dropped without a warning", missing));
            Assert.That((changed, missing), Is.EqualTo((0, 0)));
        }
    }
}
