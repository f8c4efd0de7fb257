using System;
using System.Collections.Generic;
using HeadGait.Unity;
using NUnit.Framework;
using UnityEngine;

namespace HeadGait.Tests
{
    /// <summary>
    /// <see cref="FollowHead"/> (and <see cref="HeadFollower"/> behind it): the avatar's root stands under the head,
    /// feet on the floor, facing the head's heading whatever the head's pitch and roll.
    /// </summary>
    public class FollowHeadTests
    {
        const float Frame = 1f / 72f;

        readonly TestObjects objects = new TestObjects();

        [TearDown]
        public void DestroyWhatTheTestMade() => objects.DestroyAll();

        (FollowHead follow, Transform head) Make(float floorHeight = 0, float positionSmoothing = 0, float headingSmoothing = 0)
        {
            var head = objects.New("Head").transform;
            var follow = objects.New("Avatar").AddComponent<FollowHead>();
            follow.Head = head;
            follow.FloorHeight = floorHeight;
            follow.PositionSmoothing = positionSmoothing;
            follow.HeadingSmoothing = headingSmoothing;
            return (follow, head);
        }

        static void Pose(Transform head, double x, double y, double z, double pitch, double yaw, double roll)
        {
            head.position = new Vector3((float)x, (float)y, (float)z);
            head.rotation = Quaternion.Euler((float)pitch, (float)yaw, (float)roll);
        }

        /// <summary>Heading of a rotation's forward on the horizontal plane, degrees.</summary>
        static double Heading(Quaternion q)
        {
            var f = q * Vector3.forward;
            return Math.Atan2(f.x, f.z) * 180 / Math.PI;
        }

        static double AngleBetween(double a, double b)
        {
            double d = (a - b) % 360;
            if (d < -180) d += 360;
            if (d > 180) d -= 360;
            return Math.Abs(d);
        }

        [Test]
        public void OnAGeneratedWalkTheBodyStandsUnderTheHeadFacingItsHeading()
        {
            // 20 s of a head walking at 1.3 m/s, straight then turning at 25 deg/s, looking around +-20 deg, nodding from
            // 35 deg down to 15 deg up, rolling +-6 deg with the steps and bobbing 3 cm at 1.9 steps/s.
            var (follow, head) = Make(floorHeight: 0.2f);
            var body = follow.transform;
            double x = 0.3, z = -1, course = 0;
            int frames = 0;
            for (double t = 0; t < 20; t += Frame, frames++)
            {
                if (t > 8) course += 25 * Frame;
                double c = course * Math.PI / 180;
                x += 1.3 * Frame * Math.Sin(c);
                z += 1.3 * Frame * Math.Cos(c);
                double yaw = course + 20 * Math.Sin(0.5 * t);
                double pitch = 10 + 25 * Math.Sin(1.3 * t); // Unity: positive pitch looks down
                double roll = 6 * Math.Sin(Math.PI * 1.9 * t);
                double sway = 0.02 * Math.Sin(Math.PI * 1.9 * t);
                Pose(head, x + sway * Math.Cos(c), 1.65 + 0.03 * Math.Sin(2 * Math.PI * 1.9 * t), z - sway * Math.Sin(c), pitch, yaw, roll);

                follow.Follow(Frame);

                Assert.That(body.position.x, Is.EqualTo(head.position.x).Within(1e-4), $"x at {t:F2} s");
                Assert.That(body.position.z, Is.EqualTo(head.position.z).Within(1e-4), $"z at {t:F2} s");
                Assert.That(body.position.y, Is.EqualTo(0.2f).Within(1e-6), "feet on the floor, not bobbing with the head");
                Assert.That(AngleBetween(Heading(body.rotation), yaw), Is.LessThan(0.01), $"heading at {t:F2} s");
                var up = body.rotation * new Vector3(0, 1, 0);
                Assert.That(up.y, Is.EqualTo(1).Within(1e-5), $"the body leans with the head's pitch or roll at {t:F2} s");
            }
            Assert.That(frames, Is.GreaterThan(1400));
            Assert.That(follow.Follower.IgnoredPoses, Is.EqualTo(0));
        }

        [Test]
        public void LookingStraightUpOrDownKeepsTheLastHeading()
        {
            var (follow, head) = Make();
            Pose(head, 1, 1.7, 2, 0, 40, 0);
            follow.Follow(Frame);
            Assert.That(Heading(follow.transform.rotation), Is.EqualTo(40).Within(0.01));

            // Straight down and nearly straight up (with a roll): the projected forward is noise, the heading stays.
            foreach (var (pitch, yaw, roll) in new[] { (90.0, 200.0, 0.0), (-89.0, 300.0, 10.0), (87.0, 130.0, -20.0) })
            {
                Pose(head, 1.5, 1.6, 2.5, pitch, yaw, roll);
                follow.Follow(Frame);
                Assert.That(Heading(follow.transform.rotation), Is.EqualTo(40).Within(0.01), $"pitch {pitch}");
                Assert.That(follow.transform.position.x, Is.EqualTo(1.5f).Within(1e-5), "the position still follows");
            }

            // 80 deg down still shows where the face points (cos 80 = 0.17 of the forward is horizontal).
            Pose(head, 1.5, 1.6, 2.5, 80, 120, 0);
            follow.Follow(Frame);
            Assert.That(Heading(follow.transform.rotation), Is.EqualTo(120).Within(0.01));
        }

        [Test]
        public void SmoothingTurnsTheShortWayAndLagsByItsTimeConstant()
        {
            const float tau = 0.2f;
            var (follow, head) = Make(positionSmoothing: tau, headingSmoothing: tau);
            Pose(head, 0, 1.7, 0, 0, 350, 0);
            follow.Follow(Frame);
            Assert.That(Heading(follow.transform.rotation), Is.EqualTo(-10).Within(0.01), "the first pose is taken as it is");

            // The head turns 20 deg through north and steps 1 m right at once.
            Pose(head, 1, 1.7, 0, 0, 10, 0);
            var headings = new List<double>();
            double elapsed = 0;
            while (elapsed < tau - 1e-6)
            {
                follow.Follow(Frame / 2);
                elapsed += Frame / 2;
                headings.Add(Heading(follow.transform.rotation));
            }
            double covered = 1 - Math.Exp(-elapsed / tau); // a first-order lag after elapsed seconds
            Assert.That(headings, Has.All.InRange(-10.0, 10.0), "turned the long way round through 180");
            Assert.That(headings, Is.Ordered, "the turn overshot or went back");
            Assert.That(headings[headings.Count - 1], Is.EqualTo(-10 + 20 * covered).Within(0.05));
            Assert.That(follow.transform.position.x, Is.EqualTo(covered).Within(1e-3));

            for (int i = 0; i < 200; i++) follow.Follow(Frame);
            Assert.That(Heading(follow.transform.rotation), Is.EqualTo(10).Within(0.01));
            Assert.That(follow.transform.position.x, Is.EqualTo(1).Within(1e-4));
        }

        [Test]
        public void ALostHeadPoseIsIgnoredAndTheFeetStandOnTheFloorObject()
        {
            var (follow, head) = Make(floorHeight: 0.05f);
            var floor = objects.New("XR Origin").transform;
            floor.position = new Vector3(0, 1.2f, 0);
            follow.Floor = floor;

            Pose(head, 2, 2.9, 3, 0, 90, 0);
            follow.Follow(Frame);
            Assert.That(follow.transform.position.y, Is.EqualTo(1.25f).Within(1e-6));

            head.position = new Vector3(float.NaN, 2.9f, 3);
            follow.Follow(Frame);
            Assert.That(follow.Follower.IgnoredPoses, Is.EqualTo(1));
            Assert.That(follow.transform.position.x, Is.EqualTo(2).Within(1e-6), "the body stays where the head was last seen");
            Assert.That(Heading(follow.transform.rotation), Is.EqualTo(90).Within(0.01));
        }

        [Test]
        public void ATimeConstantMustBeAFiniteNumberOfSeconds()
        {
            var follower = new HeadFollower();
            Assert.That(() => follower.HeadingTimeConstant = -1, Throws.TypeOf<ArgumentOutOfRangeException>().With.Message.Contains(nameof(HeadFollower.HeadingTimeConstant)));
            Assert.That(() => follower.PositionTimeConstant = double.NaN, Throws.TypeOf<ArgumentOutOfRangeException>());
            var (follow, _) = Make();
            follow.HeadingSmoothing = -3;
            Assert.That(follow.HeadingSmoothing, Is.EqualTo(0));
        }
    }
}
