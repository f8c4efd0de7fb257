using System;

namespace HeadGait.Synthetic
{
    /// <summary>The person (and headset fit) a synthetic stream is generated for.</summary>
    public sealed class GaitSubject
    {
        public string Name = "subject";

        /// <summary>Steps per second (cadence / 60).</summary>
        public double StepFrequency = 1.9;

        /// <summary>Coefficient of variation of stride duration, stride to stride.</summary>
        public double StrideVariability = 0.02;

        /// <summary>Vertical head acceleration amplitude (m/s^2) at 1.9 steps/s; scales with cadence.</summary>
        public double VerticalAmplitude = 2.2;

        public double ForwardAmplitude = 1.1;

        /// <summary>Lateral sway acceleration amplitude (m/s^2), stride-periodic.</summary>
        public double LateralAmplitude = 0.7;

        /// <summary>Heel-strike transient amplitude (m/s^2), damped ~15 Hz ring after each initial contact.</summary>
        public double HeelStrikeAmplitude = 1.6;

        /// <summary>Where in the step (fraction after initial contact) the vertical acceleration peaks.</summary>
        public double ShapeLag = 0.12;

        /// <summary>Share of the gait cycle in stance (toe-off at this fraction; Perry: 0.62).</summary>
        public double StanceFraction = 0.62;

        /// <summary>Right step amplitude relative to left minus one (0 = symmetric).</summary>
        public double Asymmetry = 0.0;

        /// <summary>Head roll (degrees) that follows the lateral sway at stride frequency.</summary>
        public double SwayRollDegrees = 0.8;

        /// <summary>Accelerometer white noise per axis (m/s^2).</summary>
        public double NoiseStd = 0.05;

        /// <summary>The subject's true phase map: Perry's onsets with stance stretched to <see cref="StanceFraction"/>.</summary>
        public PhaseMap PhaseMap => PhaseMap.FromStanceFraction(StanceFraction);

        /// <summary>A plausible adult, drawn from the seed.</summary>
        public static GaitSubject Random(ulong seed, string name = null)
        {
            var r = new DeterministicRandom(seed);
            return new GaitSubject
            {
                Name = name ?? $"subject-{seed}",
                StepFrequency = r.Uniform(1.65, 2.1),
                StrideVariability = r.Uniform(0.01, 0.03),
                VerticalAmplitude = r.Uniform(1.6, 2.8),
                ForwardAmplitude = r.Uniform(0.8, 1.4),
                LateralAmplitude = r.Uniform(0.5, 0.9),
                HeelStrikeAmplitude = r.Uniform(1.0, 2.2),
                ShapeLag = r.Uniform(0.09, 0.15),
                StanceFraction = r.Uniform(0.60, 0.64),
                Asymmetry = r.Uniform(-0.08, 0.08),
                SwayRollDegrees = r.Uniform(0.3, 1.2),
                NoiseStd = r.Uniform(0.03, 0.07),
            };
        }

        public override string ToString()
            => $"{Name}: {StepFrequency * 60:F0} steps/min, vertical {VerticalAmplitude:F2} m/s^2, stance {StanceFraction:P0}";
    }
}
