using System;
using System.Collections.Generic;
using HeadGait.Calibration;
using HeadGait.Synthetic;
using HeadGait.Unity;
using NUnit.Framework;
using Unity.InferenceEngine;

namespace HeadGait.Tests
{
    /// <summary>
    /// SentisEvaluator against the Unity.InferenceEngine stand-in, whose Worker computes the model's output with a second
    /// copy of the C# classifier reading the input tensor as (N, T, C): packing that transposes time and channels or mixes
    /// up windows, or unpacking that misreads the output, changes the scores and fails these tests. What Sentis itself
    /// computes from the ONNX file is checked elsewhere (training/check_onnx.mjs runs the same exports in ONNX Runtime).
    /// </summary>
    public class SentisEvaluatorTests
    {
        static GaitModels Models => GaitModels.Load(SamplePaths.FindModelsFolder(TestContext.CurrentContext.TestDirectory)
            ?? throw new AssertionException("package Models/ folder not found"));

        static LearnedClassifier Create(GaitModels models, string kind)
            => kind == SvmClassifier.Kind ? new SvmClassifier(models.Svm) : (LearnedClassifier)new BlstmClassifier(models.Blstm);

        /// <summary>Inputs 'window' (batch, T, C) and the outputs train_learned.py exports for this kind of model.</summary>
        static Model OnnxLike(LearnedClassifier c, int batch = -1, int? steps = null, int? channels = null)
        {
            var model = new Model();
            model.inputs.Add(new Model.Input { name = "window", index = 0, shape = new DynamicTensorShape(batch, steps ?? c.Features.TimeSteps, channels ?? c.Features.Channels.Length) });
            if (c is SvmClassifier)
            {
                model.outputs.Add(new Model.Output { name = "votes", index = 1 });
                model.outputs.Add(new Model.Output { name = "decision", index = 2 });
            }
            else model.outputs.Add(new Model.Output { name = "probabilities", index = 1 });
            return model;
        }

        /// <summary>
        /// The stand-in network: each input row, read as [time][channel], scored by <paramref name="reference"/>, into the
        /// float32 outputs train_learned.py exports: 'probabilities' (BLSTM), or 'votes' and 'decision' (SVM: the votes,
        /// and the pairs' decision values they come from). <paramref name="classesOut"/>: a BLSTM output of another width.
        /// </summary>
        static Func<Tensor<float>, Dictionary<string, Tensor<float>>> RunWith(LearnedClassifier reference, List<Tensor<float>> inputs, int classesOut = -1)
            => input =>
            {
                inputs?.Add(input);
                int n = input.shape[0], t = input.shape[1], ch = input.shape[2], k = classesOut > 0 ? classesOut : reference.Segments.ClassCount;
                int pairs = reference.Segments.ClassCount * (reference.Segments.ClassCount - 1) / 2;
                Assert.That(t * ch, Is.EqualTo(reference.Features.Width));
                var data = input.DownloadToArray();
                var scores = new float[n * k];
                var decision = new float[n * pairs];
                var row = new double[t * ch];
                for (int i = 0; i < n; i++)
                {
                    for (int j = 0; j < row.Length; j++) row[j] = data[i * row.Length + j];
                    var s = reference.ScoreFeatures(row);
                    for (int j = 0; j < k; j++) scores[i * k + j] = (float)s[j % s.Length];
                    if (reference is SvmClassifier)
                        for (int j = 0; j < pairs; j++) decision[i * pairs + j] = (float)reference.LastOutputs[j];
                }
                if (!(reference is SvmClassifier)) return new Dictionary<string, Tensor<float>> { ["probabilities"] = new Tensor<float>(new TensorShape(n, k), scores) };
                return new Dictionary<string, Tensor<float>>
                {
                    ["votes"] = new Tensor<float>(new TensorShape(n, k), scores),
                    ["decision"] = new Tensor<float>(new TensorShape(n, pairs), decision),
                };
            };

        /// <summary>Standardised features of consecutive windows of a generated walk, as a batch (N x T x C).</summary>
        static double[] WalkFeatures(LearnedClassifier c, int windows)
        {
            var rec = WalkingStreamGenerator.Generate("walk", GaitSubject.Random(3), new StreamScript().Stand(1).Walk(6, Foot.Left), 3);
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = c.WindowLength });
            var features = new double[windows * c.Features.Width];
            int n = 0;
            foreach (var s in rec.Samples)
                pre.Push(s.Imu, w =>
                {
                    if (w.EndTime < 2 || n == windows) return;
                    Array.Copy(c.Standardise(w), 0, features, n++ * c.Features.Width, c.Features.Width);
                });
            Assert.That(n, Is.EqualTo(windows));
            return features;
        }

        [TestCase("blstm")]
        [TestCase("svm")]
        public void PacksWindowsAsNTCAndUnpacksEachWindowsScores(string kind)
        {
            var models = Models;
            var classifier = Create(models, kind);
            var model = OnnxLike(classifier);
            var inputs = new List<Tensor<float>>();
            model.standInRun = RunWith(Create(models, kind), inputs);
            using var sentis = SentisEvaluator.Create(classifier, model, kind + ".onnx", BackendType.CPU, out string problem);
            Assert.That(problem, Is.Null);

            const int windows = 37;
            int k = classifier.OutputCount;
            var features = WalkFeatures(classifier, windows);
            var expected = new double[windows * k];
            classifier.Network.Evaluate(features, windows, expected);
            var actual = new double[windows * k];
            sentis.Evaluate(features, windows, actual);

            Assert.That(inputs.Count, Is.EqualTo(1), "one inference for the batch");
            Assert.That(inputs[0].shape.ToString(), Is.EqualTo($"({windows}, {classifier.Features.TimeSteps}, {classifier.Features.Channels.Length})"));
            Assert.That(inputs[0].disposed, Is.True, "the input tensor is disposed after the readback");
            // float32 inputs and outputs: the BLSTM's probabilities and the SVM's decision values agree to float precision
            // (the C# SVM's lanes read the features as float32 too; only pairs it decides again in double see the difference).
            Assert.That(actual, Is.EqualTo(expected).Within(1e-5));
            Assert.That(sentis.Problem, Is.Null);
            Assert.That(sentis.Inferences, Is.EqualTo(1));
            // The windows differ, so a mix-up of rows would show.
            Assert.That(new ArraySegment<double>(expected, 0, k), Is.Not.EqualTo(new ArraySegment<double>(expected, (windows - 1) * k, k)));
        }

        [Test]
        public void ATransposedPackingWouldFailTheComparison()
        {
            // The stand-in reads (N, T, C); features handed over as (N, C, T) score differently, so the check above can fail.
            var models = Models;
            var classifier = Create(models, "blstm");
            const int windows = 8;
            int t = classifier.Features.TimeSteps, ch = classifier.Features.Channels.Length, k = classifier.Segments.ClassCount;
            var features = WalkFeatures(classifier, windows);
            var transposed = new double[features.Length];
            for (int n = 0; n < windows; n++)
                for (int i = 0; i < t; i++)
                    for (int j = 0; j < ch; j++)
                        transposed[n * t * ch + j * t + i] = features[n * t * ch + i * ch + j];
            var a = new double[windows * k];
            var b = new double[windows * k];
            classifier.Network.Evaluate(features, windows, a);
            classifier.Network.Evaluate(transposed, windows, b);
            Assert.That(b, Is.Not.EqualTo(a).Within(1e-3));
        }

        [TestCase("blstm")]
        [TestCase("svm")]
        public void ThePipelineWithSentisPredictsWhatItPredictsWithTheCSharpNetwork(string kind)
        {
            var models = Models;
            var samples = WalkingStreamGenerator.Generate("w", GaitSubject.Random(8), new StreamScript().Stand(2).Walk(10, Foot.Right).Stand(2), 8).Samples;
            var expected = WithTheCSharpNetwork(Create(models, kind), samples);
            var actual = ThroughSentis(Create(models, kind), Create(models, kind), samples, out int inferences);

            Assert.That(actual.Count, Is.EqualTo(expected.Count));
            Assert.That(inferences, Is.GreaterThan(100).And.LessThan(expected.Count), "batches of the frame's windows");
            AssertSamePredictions(actual, expected);
            Assert.That(expected.FindAll(p => p.IsWalking).Count, Is.GreaterThan(expected.Count / 3));
        }

        /// <summary>
        /// A wearer profile's shifts of the output biases (the SVM's pair intercepts, the BLSTM's class biases), fitted on a
        /// calm wearer's calibration walk with ankle trackers, act on the model's outputs in C# after any evaluator: through
        /// Sentis, which runs the shipped export and knows nothing of the profile, the pipeline shows on the wearer's other
        /// walk what it shows with the C# network, and that is not what the same profile with its shifts zeroed shows.
        /// </summary>
        [TestCase("svm")]
        [TestCase("blstm")]
        public void AWearersOutputShiftsActThroughSentisAsThroughTheCSharpNetwork(string kind)
        {
            var models = Models;
            var wearer = CalibrationTests.Wearer();
            var walk = CalibrationTests.Walk(wearer);
            var (left, right) = SyntheticAnkles.From(walk, 72, 3);
            var only = new GaitModels { Threshold = models.Threshold, Correlation = models.Correlation };
            if (kind == SvmClassifier.Kind) only.Svm = models.Svm;
            else only.Blstm = models.Blstm;
            var profile = new CalibrationSession(CalibrationTests.Unlabelled(walk), left, right).Fit(only, "calm-wearer");
            var shift = profile.AdjustmentFor(kind)?.BiasShift;
            Assert.That(shift, Is.Not.Null.And.Some.Not.EqualTo(0), $"the {kind} refit shifts some output bias");
            var zeroed = WearerProfile.Parse(profile.Serialize());
            zeroed.AdjustmentFor(kind).BiasShift = new double[shift.Length];

            LearnedClassifier Adapted(WearerProfile p)
            {
                var adapted = p.Apply(only);
                Assert.That(adapted.Problems, Is.Empty);
                return kind == SvmClassifier.Kind ? new SvmClassifier(adapted.Svm) : (LearnedClassifier)new BlstmClassifier(adapted.Blstm);
            }
            var other = WalkingStreamGenerator.Generate("other-walk", wearer, new StreamScript().Stand(2).Walk(20, Foot.Right).Stand(1).Walk(20, Foot.Left, -30).Stand(2), 911).Samples;
            var expected = WithTheCSharpNetwork(Adapted(profile), other);
            var unshifted = WithTheCSharpNetwork(Adapted(zeroed), other);
            var actual = ThroughSentis(Adapted(profile), Create(models, kind), other, out _);

            Assert.That(actual.Count, Is.EqualTo(expected.Count));
            int moved = 0;
            for (int i = 0; i < expected.Count; i++)
                if (expected[i].Left != unshifted[i].Left || expected[i].Right != unshifted[i].Right) moved++;
            Assert.That(moved, Is.GreaterThan(expected.Count / 100), "the shifts move the walking classes shown");
            AssertSamePredictions(actual, expected);
        }

        /// <summary>The predictions of a pipeline pushed one sample at a time, scored by the classifier's C# network.</summary>
        static List<GaitPrediction> WithTheCSharpNetwork(LearnedClassifier classifier, IReadOnlyList<RecordedSample> samples)
        {
            var plain = new GaitPipeline(classifier);
            var predictions = new List<GaitPrediction>();
            plain.FrameProduced += (p, f) => predictions.Add(p);
            foreach (var s in samples) plain.Push(s.Imu);
            return predictions;
        }

        /// <summary>
        /// The predictions of <paramref name="classifier"/> scored by a Sentis evaluator whose stand-in network is
        /// <paramref name="reference"/>, the batches run inline at a frame every 3 samples (about 33 fps), as the Sentis
        /// component runs them.
        /// </summary>
        static List<GaitPrediction> ThroughSentis(LearnedClassifier classifier, LearnedClassifier reference, IReadOnlyList<RecordedSample> samples, out int inferences)
        {
            string kind = classifier is SvmClassifier ? SvmClassifier.Kind : BlstmClassifier.Kind;
            var model = OnnxLike(classifier);
            model.standInRun = RunWith(reference, null);
            using var sentis = SentisEvaluator.Create(classifier, model, kind + ".onnx", BackendType.GPUCompute, out string problem);
            Assert.That(problem, Is.Null);
            classifier.Evaluator = sentis;
            var runner = new GaitBatchRunner(new GaitPipeline(classifier));
            var inline = new InlineBatchScheduler(runner);
            var predictions = new List<GaitPrediction>();
            runner.Pipeline.FrameProduced += (p, f) => predictions.Add(p);
            for (int i = 0; i < samples.Count; i++)
            {
                runner.Push(samples[i].Imu);
                if (i % 3 == 2) runner.Step(inline);
            }
            runner.Step(inline);
            Assert.That(sentis.Problem, Is.Null);
            inferences = sentis.Inferences;
            return predictions;
        }

        static void AssertSamePredictions(List<GaitPrediction> actual, List<GaitPrediction> expected)
        {
            Assert.That(actual.Count, Is.EqualTo(expected.Count));
            for (int i = 0; i < expected.Count; i++)
            {
                Assert.That(actual[i].Left, Is.EqualTo(expected[i].Left), $"window {i}");
                Assert.That(actual[i].Right, Is.EqualTo(expected[i].Right), $"window {i}");
                Assert.That(actual[i].StridePosition, Is.EqualTo(expected[i].StridePosition).Within(1e-3), $"window {i}");
            }
        }

        [Test]
        public void AModelWhoseInputDoesNotFitIsRefusedWithTheReason()
        {
            var blstm = Create(Models, "blstm");
            int t = blstm.Features.TimeSteps, c = blstm.Features.Channels.Length;
            var transposed = OnnxLike(blstm, steps: c, channels: t);
            Assert.That(SentisEvaluator.Create(blstm, transposed, "blstm.onnx", BackendType.CPU, out string problem), Is.Null);
            Assert.That(problem, Does.Contain("blstm.onnx").And.Contain($"(batch, {t}, {c})"));
            Assert.That(transposed.standInWorkersAlive, Is.EqualTo(0), "no worker made for a refused model");

            var renamed = OnnxLike(blstm);
            renamed.inputs[0] = new Model.Input { name = "input", shape = new DynamicTensorShape(-1, t, c) };
            Assert.That(SentisEvaluator.Create(blstm, renamed, "blstm.onnx", BackendType.CPU, out problem), Is.Null);
            Assert.That(problem, Does.Contain("no input 'window'"));

            Assert.That(SentisEvaluator.Create(blstm, null, "(none)", BackendType.CPU, out problem), Is.Null);
            Assert.That(problem, Does.Contain("no ONNX model"));
        }

        [Test]
        public void TheOtherModelsExportIsRefused()
        {
            var models = Models;
            var svm = Create(models, "svm");
            var blstmExport = OnnxLike(Create(models, "blstm"));
            Assert.That(SentisEvaluator.Create(svm, blstmExport, "blstm.onnx", BackendType.CPU, out string problem), Is.Null);
            Assert.That(problem, Does.Contain("no output 'decision'"));
        }

        [Test]
        public void AnOutputOfTheWrongShapeFallsBackToTheCSharpNetworkAndSaysWhy()
        {
            var models = Models;
            var classifier = Create(models, "blstm");
            int k = classifier.Segments.ClassCount;
            var model = OnnxLike(classifier);
            model.standInRun = RunWith(Create(models, "blstm"), null, classesOut: k - 1);
            var sentis = SentisEvaluator.Create(classifier, model, "blstm.onnx", BackendType.CPU, out string problem);
            Assert.That(problem, Is.Null, "the input fits; the output shows only when run");

            const int windows = 5;
            var features = WalkFeatures(classifier, windows);
            var expected = new double[windows * k];
            classifier.Network.Evaluate(features, windows, expected);
            var actual = new double[windows * k];
            sentis.Evaluate(features, windows, actual);
            Assert.That(actual, Is.EqualTo(expected), "the C# network's scores, exactly");
            Assert.That(sentis.Problem, Does.Contain("'probabilities'").And.Contain($"({windows}, {k})"));
            Assert.That(sentis.Inferences, Is.EqualTo(0));

            sentis.Evaluate(features, windows, actual);
            Assert.That(actual, Is.EqualTo(expected));
            Assert.That(model.standInWorkersAlive, Is.EqualTo(1));
            sentis.Dispose();
            Assert.That(model.standInWorkersAlive, Is.EqualTo(0), "Dispose frees the worker");
        }

        static void SetField(object target, string field, object value)
        {
            var f = target.GetType().GetField(field, System.Reflection.BindingFlags.Instance | System.Reflection.BindingFlags.NonPublic);
            Assert.That(f, Is.Not.Null, $"{target.GetType().Name}.{field}");
            f.SetValue(target, value);
        }

        /// <summary>
        /// In a scene the Sentis component (default execution order) is enabled before the animator's Awake (order 100):
        /// asking the animator for its pipeline then builds it, which raises Rebuilt into the handler just subscribed. Only
        /// one worker may be left, and disabling must free it.
        /// </summary>
        [Test]
        public void EnabledBeforeTheAnimatorsAwakeItMakesOneWorkerAndFreesIt()
        {
            string folder = SamplePaths.FindModelsFolder(TestContext.CurrentContext.TestDirectory);
            var models = Models;
            var model = OnnxLike(Create(models, "blstm"));
            model.standInRun = RunWith(Create(models, "blstm"), null);

            var avatar = new UnityEngine.GameObject("Avatar");
            try
            {
                avatar.SetActive(false); // as a scene loads: both components present before either wakes
                var animator = avatar.AddComponent<GaitLegAnimator>();
                SetField(animator, "classifier", GaitClassifierKind.Blstm);
                SetField(animator, "blstmModel", new UnityEngine.TextAsset(System.IO.File.ReadAllBytes(System.IO.Path.Combine(folder, GaitModels.BlstmFile))) { name = "blstm" });
                SetField(animator, "corTemplate", new UnityEngine.TextAsset(System.IO.File.ReadAllText(System.IO.Path.Combine(folder, GaitModels.CorrelationFile))) { name = "cor_template" });
                var sentis = avatar.AddComponent<SentisGaitModels>();
                SetField(sentis, "blstmModel", new global::Unity.InferenceEngine.ModelAsset { name = "blstm", standInModel = model });

                avatar.SetActive(true);
                Assert.That(animator.Pipeline.Classifier, Is.InstanceOf<BlstmClassifier>());
                Assert.That(sentis.Evaluator, Is.Not.Null, "Sentis runs the BLSTM");
                Assert.That(model.standInWorkersAlive, Is.EqualTo(1), "one worker, none left behind by the nested rebuild");

                animator.Build(); // a rebuild replaces the worker
                Assert.That(model.standInWorkersAlive, Is.EqualTo(1));
                sentis.enabled = false;
                Assert.That(model.standInWorkersAlive, Is.EqualTo(0), "disabling frees the worker");
            }
            finally
            {
                UnityEngine.Object.DestroyImmediate(avatar);
            }
        }
    }
}
