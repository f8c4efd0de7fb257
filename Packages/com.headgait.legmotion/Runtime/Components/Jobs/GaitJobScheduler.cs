using System;
using System.Runtime.InteropServices;
using Unity.Jobs;

namespace HeadGait.Unity
{
    /// <summary>
    /// Runs a <see cref="GaitBatchRunner"/>'s batches as Unity jobs on a worker thread.
    /// <para>
    /// Why a managed job: the pipeline is managed C# (classes, arrays, virtual calls), which Burst cannot compile and a job
    /// struct cannot hold (job fields must be value types). The job therefore carries a <see cref="GCHandle"/> (a value type)
    /// to the runner and is not Burst-compiled; Unity runs such jobs as ordinary managed code on its worker threads. The
    /// handle is allocated once per runner, so scheduling allocates nothing.
    /// </para>
    /// </summary>
    public sealed class GaitJobScheduler : IGaitBatchScheduler, IDisposable
    {
        GCHandle runner;
        JobHandle job;

        public GaitJobScheduler(GaitBatchRunner runner)
        {
            if (runner == null) throw new ArgumentNullException(nameof(runner));
            this.runner = GCHandle.Alloc(runner);
        }

        public void Schedule()
        {
            if (!runner.IsAllocated) throw new ObjectDisposedException(nameof(GaitJobScheduler));
            job = new GaitBatchJob { Runner = runner }.Schedule();
            JobHandle.ScheduleBatchedJobs(); // start now, not at the next sync point
        }

        public void Complete()
        {
            job.Complete();
            job = default;
        }

        /// <summary>Completes any batch still running and frees the handle.</summary>
        public void Dispose()
        {
            job.Complete();
            job = default;
            if (runner.IsAllocated) runner.Free();
        }

        /// <summary>The job: one batch of the runner the handle points to.</summary>
        struct GaitBatchJob : IJob
        {
            public GCHandle Runner;

            public void Execute() => ((GaitBatchRunner)Runner.Target).ExecuteBatch();
        }
    }
}
