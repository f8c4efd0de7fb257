using System;
using System.Collections.Generic;
using System.Linq;
using System.Text;

namespace HeadGait.Study
{
    /// <summary>What the operator can do; the operator view shows one control each.</summary>
    public enum OperatorCommand
    {
        /// <summary>The participant starts walking the path (baseline walk or a VR trial).</summary>
        Start,
        /// <summary>Saves the current step (the SSQ form, the walk) and moves on.</summary>
        Next,
        /// <summary>The walk is walked again (participant stumbled, tracking lost); the step stays.</summary>
        RepeatTrial,
        /// <summary>Ends the session here; everything saved stays, and opening the id again resumes.</summary>
        Abort,
    }

    /// <summary>
    /// The operator's side of a study run, engine-free so it can be tested: opens a participant (new, or resumed at the
    /// first unfinished step; an id with data is never started over), runs the operator's commands against the
    /// <see cref="StudySession"/>, holds the SSQ form of the current step, and says which avatar condition the scene
    /// must show. A failed write (full or read-only disk) never throws out of here: it becomes <see cref="Error"/>, shown
    /// on the operator screen, and the command can be given again once the cause is fixed.
    /// </summary>
    public sealed class StudyOperator : IDisposable
    {
        readonly StudyConfig config;
        readonly JournalFileAccess files;
        bool walking;

        /// <param name="files">The journal's file access (tests stand in full disks and crashes); null: the real file system.</param>
        public StudyOperator(string dataFolder, StudyConfig config, JournalFileAccess files = null)
        {
            if (string.IsNullOrEmpty(dataFolder)) throw new ArgumentException("The study needs a data folder.");
            config.Validate();
            DataFolder = dataFolder;
            this.config = config;
            this.files = files;
        }

        public string DataFolder { get; }

        /// <summary>The open participant's session; null while no participant is open.</summary>
        public StudySession Session { get; private set; }

        /// <summary>The SSQ of the current step, filled in from the VR panel or the keyboard.</summary>
        public SsqForm Ssq { get; } = new SsqForm();

        /// <summary>The last failure, for the operator screen; cleared by the next command that succeeds.</summary>
        public string Error { get; private set; }

        /// <summary>The last thing worth telling the operator (participant started or resumed, SSQ saved, ...).</summary>
        public string Notice { get; private set; }

        public StudyStep? Current => Session?.Current;

        /// <summary>True between Start and Next of a walk.</summary>
        public bool Walking => walking;

        /// <summary>
        /// The VR condition the scene shows: the condition of the current trial (from the moment its step is reached, so
        /// the participant is ready when the walk starts), or null (no avatar) at every other step.
        /// </summary>
        public string ActiveCondition => Current is StudyStep s && s.Kind == StudyStepKind.Trial ? s.Condition : null;

        /// <summary>True while the current step is an SSQ, i.e. while the VR panel should be up.</summary>
        public bool SsqOpen => Current is StudyStep s && s.IsSsq;

        /// <summary>
        /// Opens a participant: resumes one that has data, starts a new one otherwise. Refused while the id is open in another
        /// session (this application or another). A resumed SSQ step whose answer was saved shows it on the form.
        /// </summary>
        public bool Open(string participantId)
        {
            return Try(() =>
            {
                if (Session != null) throw new InvalidOperationException($"Participant {Session.Participant} is open; abort it first.");
                string id = ParticipantIds.Canonical(participantId);
                Session = StudySession.OpenOrStart(DataFolder, id, config, out bool resumed, files);
                walking = false;
                Ssq.Clear();
                var step = Session.Current;
                var notice = new StringBuilder(resumed
                    ? $"Resumed participant {id} at step {step.Index + 1} of {Session.Steps.Count} ({Describe(step)}); nothing saved before is changed."
                    : $"Started participant {id}; data goes to {Session.JournalPath}.");
                if (Session.RecoveredTornLine) notice.Append($" A half-written last line from a crash ({Session.TornBytes} bytes) was cut; it had never been acknowledged.");
                if (Session.Damage.Count > 0) notice.Append($" {Session.Damage.Count} damaged line(s) in the journal are kept as they are and not used ({Session.Damage[0]}).");
                var saved = step.IsSsq ? Session.SsqOf(step.Index) : null;
                if (saved != null)
                {
                    Ssq.Load(saved);
                    notice.Append($" This step's SSQ was saved before the session stopped ({SimulatorSicknessQuestionnaire.Score(saved)}): Next goes on without saving it again; a changed rating is saved as a correction.");
                }
                Notice = notice.ToString();
            });
        }

        /// <summary>Closes the open participant without writing anything (the application quits); everything saved stays and the id is free again.</summary>
        public void Dispose()
        {
            Session?.Dispose();
            Session = null;
            walking = false;
        }

        public bool CanDo(OperatorCommand command)
        {
            if (Session == null) return false;
            var step = Session.Current;
            bool isWalk = step.Kind == StudyStepKind.Trial || step.Kind == StudyStepKind.BaselineWalk;
            switch (command)
            {
                case OperatorCommand.Start: return isWalk && !walking;
                case OperatorCommand.RepeatTrial: return isWalk && walking;
                case OperatorCommand.Next:
                    if (step.Kind == StudyStepKind.Done) return false;
                    if (isWalk) return walking;
                    if (step.IsSsq) return Ssq.IsComplete;
                    return true;
                case OperatorCommand.Abort: return true;
                default: return false;
            }
        }

        /// <summary>Runs a command; false (with <see cref="Error"/> set) when it is not possible now or could not be saved.</summary>
        public bool Do(OperatorCommand command)
        {
            if (Session == null)
            {
                Error = "Enter a participant id first.";
                return false;
            }
            if (!CanDo(command))
            {
                Error = $"{command} is not possible at step {Describe(Session.Current)}" + (Session.Current.IsSsq && command == OperatorCommand.Next
                    ? $": {Ssq.AnsweredCount} of {SimulatorSicknessQuestionnaire.ItemCount} SSQ items are rated."
                    : ".");
                return false;
            }
            switch (command)
            {
                case OperatorCommand.Start:
                    return Try(() =>
                    {
                        Session.Event("walk-started");
                        walking = true;
                        Notice = "Walking: Start, Turn, End.";
                    });
                case OperatorCommand.RepeatTrial:
                    return Try(() =>
                    {
                        Session.Event("walk-repeated");
                        Notice = "Walk repeated: the participant walks the path again.";
                    });
                case OperatorCommand.Next:
                    return Try(Next);
                default:
                    return Abort();
            }
        }

        void Next()
        {
            var step = Session.Current;
            if (step.IsSsq)
            {
                var ratings = Ssq.Ratings();
                var saved = Session.SsqOf(step.Index);
                bool same = saved != null && saved.SequenceEqual(ratings);
                // Saved already (a resumed step, or a retry after the "done" line failed): not saved twice.
                var scores = same ? SimulatorSicknessQuestionnaire.Score(ratings) : Session.AnswerSsq(ratings);
                Session.CompleteStep();
                Ssq.Clear();
                Notice = saved != null && !same ? $"SSQ corrected and saved: {scores} (the first answer stays in the journal)." : $"SSQ saved: {scores}.";
                return;
            }
            if (walking) Session.Event("walk-finished");
            walking = false;
            Session.CompleteStep();
            Notice = Session.Current.Kind == StudyStepKind.Done ? $"Participant {Session.Participant} is done." : $"{Describe(step)} saved.";
        }

        bool Abort()
        {
            string participant = Session.Participant;
            int step = Session.Current.Index;
            bool saved = Try(() => Session.Event("aborted"));
            // The session closes even when the abort note could not be written: every answer is already on disk.
            Session.Dispose();
            Session = null;
            walking = false;
            Ssq.Clear();
            Notice = $"Participant {participant} aborted at step {step + 1}; open the id again to resume.";
            return saved;
        }

        /// <summary>Saves a demographics answer (age, gender, ...) at the demographics step.</summary>
        public bool SetDemographic(string key, string value)
        {
            if (Session == null || Session.Current.Kind != StudyStepKind.Demographics)
            {
                Error = "Demographics are entered at the demographics step.";
                return false;
            }
            return Try(() => Session.Answer(key, value));
        }

        bool Try(Action action)
        {
            try
            {
                action();
                Error = null;
                return true;
            }
            catch (Exception e) when (e is StudyStorageException || e is ArgumentException || e is InvalidOperationException)
            {
                Error = e.Message;
                return false;
            }
        }

        /// <summary>What the operator screen shows, in the order it shows it.</summary>
        public OperatorScreen Screen()
        {
            var screen = new OperatorScreen { Error = Error, Notice = Notice };
            if (Session == null)
            {
                screen.Instruction = "Enter the participant id (letters, digits, '-' or '_') and press Open. An id with data resumes where it stopped.";
                return screen;
            }
            var step = Session.Current;
            screen.Participant = Session.Participant;
            screen.Step = $"Step {Math.Min(step.Index + 1, Session.Steps.Count)} of {Session.Steps.Count}: {Describe(step)}";
            foreach (var s in Session.Steps)
                if (s.Kind == StudyStepKind.Trial)
                {
                    screen.ConditionOrder.Add(s.Condition);
                    if (s.Index == step.Index || (step.Kind == StudyStepKind.ConditionSsq && s.Condition == step.Condition)) screen.CurrentCondition = screen.ConditionOrder.Count - 1;
                }
            screen.Instruction = InstructionFor(step);
            return screen;
        }

        string InstructionFor(StudyStep step)
        {
            switch (step.Kind)
            {
                case StudyStepKind.Demographics: return "Enter age and gender, then Next.";
                case StudyStepKind.BaselineWalk:
                case StudyStepKind.Trial:
                    string where = step.Kind == StudyStepKind.Trial ? $"in VR with {step.Condition}" : "in the real room, without the headset";
                    return walking
                        ? $"The participant walks {where} from Start over Turn to End ({Session.Config.PathLengthMeters:0.#} m). Next when they reach End; Repeat trial to walk again."
                        : $"Place the participant at Start ({where}); press Start when they begin walking.";
                case StudyStepKind.PreExposureSsq:
                case StudyStepKind.BaselineSsq:
                case StudyStepKind.ConditionSsq:
                    return $"SSQ: {Ssq.AnsweredCount} of {SimulatorSicknessQuestionnaire.ItemCount} rated (VR controller, or keys 0-3 and arrows). Next saves it.";
                case StudyStepKind.Rest: return $"Rest ({Session.Config.RestSeconds:0} s, headset off); Next when rested.";
                default: return "Session complete. Run 'headgait study summarize' on the data folder.";
            }
        }

        static string Describe(StudyStep step) => step.Condition == null ? step.Kind.ToString() : $"{step.Kind} ({step.Condition})";
    }

    /// <summary>The operator screen's content; the view only lays it out.</summary>
    public sealed class OperatorScreen
    {
        /// <summary>Null while no participant is open.</summary>
        public string Participant;
        public string Step;
        /// <summary>The participant's counterbalanced condition order.</summary>
        public List<string> ConditionOrder = new List<string>();
        /// <summary>Index into <see cref="ConditionOrder"/> of the condition being walked or rated; -1 otherwise.</summary>
        public int CurrentCondition = -1;
        public string Instruction;
        public string Notice;
        /// <summary>A failure (e.g. the disk is full or read-only); shown prominently until a command succeeds.</summary>
        public string Error;
    }
}
