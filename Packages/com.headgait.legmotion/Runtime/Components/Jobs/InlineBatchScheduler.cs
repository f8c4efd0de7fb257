namespace HeadGait.Unity
{
    /// <summary>
    /// Runs each batch at once on the calling (main) thread: for evaluators that must be called there, such as Sentis,
    /// which schedules its own jobs and GPU work. The frame order is that of the job: a batch's frame is published by the
    /// <see cref="GaitBatchRunner.Step"/> that ran it.
    /// </summary>
    public sealed class InlineBatchScheduler : IGaitBatchScheduler
    {
        readonly GaitBatchRunner runner;

        public InlineBatchScheduler(GaitBatchRunner runner) => this.runner = runner ?? throw new System.ArgumentNullException(nameof(runner));

        public void Schedule() => runner.ExecuteBatch();

        public void Complete() { }
    }
}
