namespace HeadGait.Unity
{
    /// <summary>
    /// Runs <see cref="GaitBatchRunner.ExecuteBatch"/> somewhere: on Unity's job system (<see cref="GaitJobScheduler"/>),
    /// or inline where no job system is wanted.
    /// </summary>
    public interface IGaitBatchScheduler
    {
        /// <summary>Starts the runner's batch; must not wait for it.</summary>
        void Schedule();

        /// <summary>Returns once the batch started by the last <see cref="Schedule"/> has finished.</summary>
        void Complete();
    }
}
