using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace HeadGait.Tooling
{
    /// <summary>
    /// Draws the generated clips as side-view stick figures (facing right; left side blue, right side orange) at a row of
    /// stride positions, labelled with each foot's gait phase; a dot under a foot marks it on the ground.
    /// </summary>
    public static class GaitStickFigureSvg
    {
        const double Scale = 150;      // pixels per metre
        const double Cell = 118;       // pixels per frame
        const double RowHeight = 370;
        const double Margin = 130;
        const string LeftColour = "#1f6fb4", RightColour = "#e8730c";
        static readonly CultureInfo Ci = CultureInfo.InvariantCulture;

        /// <summary>One row of the picture: a clip shown at the given stride positions.</summary>
        public sealed class Row
        {
            public LocomotionState Clip;
            public string Title;
            public double[] Positions;
        }

        /// <summary>The default rows: Walking over one stride, and the left foot's start and finish over their steps.</summary>
        public static List<Row> DefaultRows(GaitClips clips, int frames = 12)
        {
            var walking = new double[frames + 1];
            for (int i = 0; i <= frames; i++) walking[i] = (double)i / frames;
            double r = clips.InitialContact(Foot.Right);
            var step = new double[7];
            for (int i = 0; i < step.Length; i++) step[i] = r + (1 - r) * i / (step.Length - 1);
            return new List<Row>
            {
                new Row { Clip = LocomotionState.Walking, Title = "Walking", Positions = walking },
                new Row { Clip = LocomotionState.StartWalkLeft, Title = "Start Walk Left", Positions = step },
                new Row { Clip = LocomotionState.FinishWalkLeft, Title = "Finish Walk Left", Positions = step },
            };
        }

        public static string Write(GaitClips clips, IList<Row> rows)
        {
            int columns = 0;
            foreach (var row in rows) columns = Math.Max(columns, row.Positions.Length);
            double width = Margin + columns * Cell + 20, height = rows.Count * RowHeight + 60;
            var svg = new StringBuilder();
            svg.Append(F("<svg xmlns='http://www.w3.org/2000/svg' width='{0:F0}' height='{1:F0}' font-family='sans-serif' font-size='12'>", width, height));
            svg.Append("<rect width='100%' height='100%' fill='white'/>");
            svg.Append(F("<text x='10' y='24' font-size='16'>HeadGait gait clips: stride position s (0 = left initial contact, right at {0:F3}); ", clips.InitialContact(Foot.Right)));
            svg.Append(F("<tspan fill='{0}'>left</tspan> / <tspan fill='{1}'>right</tspan> phase; dot = foot on the ground</text>", LeftColour, RightColour));
            for (int ri = 0; ri < rows.Count; ri++)
            {
                var row = rows[ri];
                double ground = 60 + ri * RowHeight + 290;
                svg.Append(F("<text x='10' y='{0:F0}' font-size='14' font-weight='bold'>{1}</text>", ground - 150, row.Title));
                svg.Append(F("<line x1='{0:F0}' y1='{1:F1}' x2='{2:F0}' y2='{1:F1}' stroke='#888'/>", Margin - 10, ground, Margin + row.Positions.Length * Cell));
                for (int i = 0; i < row.Positions.Length; i++)
                    Figure(svg, clips, row.Clip, row.Positions[i], Margin + (i + 0.5) * Cell, ground);
            }
            svg.Append("</svg>");
            return svg.ToString();
        }

        static void Figure(StringBuilder svg, GaitClips clips, LocomotionState clip, double s, double cx, double ground)
        {
            var pose = clips.Pose(clip, s >= 1 ? 1 - 1e-9 : s);
            var hip = new SagittalPoint(0, pose.HipHeight);
            double tilt = pose.PelvicTilt * Math.PI / 180;
            SagittalPoint Up(SagittalPoint from, double length, double forwardLean) => from + new SagittalPoint(length * Math.Sin(forwardLean), length * Math.Cos(forwardLean));
            var shoulder = Up(hip, 0.08 + 0.46, tilt);
            var head = Up(hip, 0.08 + 0.56 + 0.1, tilt);
            (double X, double Y) P(SagittalPoint p) => (cx + p.X * Scale, ground - p.Y * Scale);
            void Line(SagittalPoint a, SagittalPoint b, string colour, double w)
            {
                var (x1, y1) = P(a);
                var (x2, y2) = P(b);
                svg.Append(F("<line x1='{0:F1}' y1='{1:F1}' x2='{2:F1}' y2='{3:F1}' stroke='{4}' stroke-width='{5}' stroke-linecap='round'/>", x1, y1, x2, y2, colour, w));
            }
            foreach (Foot side in new[] { Foot.Right, Foot.Left }) // the far (right) side first
            {
                string colour = side == Foot.Left ? LeftColour : RightColour;
                double arm = (side == Foot.Left ? pose.LeftArm : pose.RightArm) * Math.PI / 180 + tilt;
                var elbow = shoulder + new SagittalPoint(0.3 * Math.Sin(arm), -0.3 * Math.Cos(arm));
                var hand = elbow + new SagittalPoint(0.26 * Math.Sin(arm + 0.26), -0.26 * Math.Cos(arm + 0.26));
                Line(shoulder, elbow, colour, 3);
                Line(elbow, hand, colour, 3);
                var leg = pose.Leg(side);
                Line(hip, hip + leg.Knee, colour, 4);
                Line(hip + leg.Knee, hip + leg.Ankle, colour, 4);
                Line(hip + leg.Ankle, hip + leg.Heel, colour, 3);
                Line(hip + leg.Heel, hip + leg.Ball, colour, 3);
                Line(hip + leg.Ball, hip + leg.Toe, colour, 3);
                if (pose.FootHeight(side) < 0.002)
                {
                    var lowest = leg.Heel.Y <= leg.Ball.Y ? leg.Heel : leg.Ball;
                    var (x, _) = P(hip + lowest);
                    svg.Append(F("<circle cx='{0:F1}' cy='{1:F1}' r='4' fill='{2}'/>", x, ground + 6, colour));
                }
            }
            Line(hip, shoulder, "#333", 5);
            var (hx, hy) = P(head);
            svg.Append(F("<circle cx='{0:F1}' cy='{1:F1}' r='{2:F1}' fill='white' stroke='#333' stroke-width='3'/>", hx, hy, 0.11 * Scale));
            svg.Append(F("<text x='{0:F1}' y='{1:F1}' text-anchor='middle'>s={2:F2}</text>", cx, ground + 26, PhaseMap.Wrap(s)));
            svg.Append(F("<text x='{0:F1}' y='{1:F1}' text-anchor='middle' fill='{2}'>L {3}</text>", cx, ground + 42, LeftColour, GaitPhases.ShortName(clips.Map.PhaseAt(Foot.Left, s))));
            svg.Append(F("<text x='{0:F1}' y='{1:F1}' text-anchor='middle' fill='{2}'>R {3}</text>", cx, ground + 58, RightColour, GaitPhases.ShortName(clips.Map.PhaseAt(Foot.Right, s))));
        }

        static string F(string format, params object[] args) => string.Format(Ci, format, args);
    }
}
