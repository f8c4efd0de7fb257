// Stand-in for the parts of Unity's job system the package uses, after UnityCsReference
// Runtime/Jobs/Managed/IJob.cs (IJob, IJobExtensions.Schedule) and Runtime/Jobs/ScriptBindings/JobHandle.bindings.cs (JobHandle).
// Signatures match those files. Behaviour: a scheduled job runs when its handle is completed, on the completing thread,
// which is the latest a real worker could run it; so a test that reads results without completing sees none. Slots are
// reused, so scheduling allocates nothing once warm (like the real job system).
using System.Collections.Generic;

namespace Unity.Jobs
{
    // IJob.cs: public interface IJob { void Execute(); }
    public interface IJob
    {
        void Execute();
    }

    // JobHandle.bindings.cs: public struct JobHandle with Complete(), IsCompleted, static ScheduleBatchedJobs().
    public struct JobHandle
    {
        internal PendingJob job;
        internal int version;

        public void Complete()
        {
            job?.RunIfPending(version);
        }

        public bool IsCompleted => job == null || !job.IsPending(version);

        public static void ScheduleBatchedJobs() { }
    }

    // IJob.cs: public static JobHandle Schedule<T>(this T jobData, JobHandle dependsOn = new JobHandle()) where T : struct, IJob
    public static class IJobExtensions
    {
        public static JobHandle Schedule<T>(this T jobData, JobHandle dependsOn = new JobHandle()) where T : struct, IJob
            => PendingJob<T>.Take(jobData, dependsOn);

        // IJob.cs: public static void Run<T>(this T jobData) where T : struct, IJob
        public static void Run<T>(this T jobData) where T : struct, IJob => jobData.Execute();
    }

    internal abstract class PendingJob
    {
        protected int version;
        protected bool pending;
        protected JobHandle dependsOn;

        public bool IsPending(int v) => pending && v == version;

        public void RunIfPending(int v)
        {
            if (!IsPending(v)) return;
            dependsOn.Complete();
            pending = false;
            Execute();
        }

        protected abstract void Execute();
    }

    internal sealed class PendingJob<T> : PendingJob where T : struct, IJob
    {
        static readonly List<PendingJob<T>> slots = new List<PendingJob<T>>();
        T data;

        public static JobHandle Take(T data, JobHandle dependsOn)
        {
            PendingJob<T> slot = null;
            foreach (var s in slots)
                if (!s.pending) { slot = s; break; }
            if (slot == null)
            {
                slot = new PendingJob<T>();
                slots.Add(slot);
            }
            slot.data = data;
            slot.dependsOn = dependsOn;
            slot.pending = true;
            slot.version++;
            return new JobHandle { job = slot, version = slot.version };
        }

        protected override void Execute() => data.Execute();
    }
}
