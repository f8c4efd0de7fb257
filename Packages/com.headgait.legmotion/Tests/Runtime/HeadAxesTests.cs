using HeadGait.Unity;
using NUnit.Framework;
using UnityEngine;

namespace HeadGait.Tests
{
    /// <summary>
    /// The package's axis conventions. In Unity it runs against the engine; under `dotnet test` against the stand-ins in
    /// dotnet/UnityStubs (real quaternion math, Unity's Euler order).
    /// </summary>
    public class HeadAxesTests
    {
        const float G = HeadAxes.StandardGravity;

        [Test]
        public void UnityAxesMapToForwardLeftUp()
        {
            var f = HeadAxes.FromUnityLocal(new Vector3(1, 2, 3)); // right 1, up 2, forward 3
            Assert.That(f.x, Is.EqualTo(3f));
            Assert.That(f.y, Is.EqualTo(-1f));
            Assert.That(f.z, Is.EqualTo(2f));
        }

        [Test]
        public void HeadAtRestReadsGravityUpWhicheverWayItFaces()
        {
            foreach (float yaw in new[] { 0f, 90f, -135f })
            {
                var f = HeadAxes.SpecificForceFromLinear(new Vector3(0, 0, 0), Quaternion.Euler(new Vector3(0, yaw, 0)));
                Assert.That(f.z, Is.EqualTo(G).Within(1e-4f));
                Assert.That(f.x, Is.EqualTo(0f).Within(1e-4f));
                Assert.That(f.y, Is.EqualTo(0f).Within(1e-4f));
            }
        }

        [Test]
        public void AccelerationTowardsWhereTheHeadLooksIsForward()
        {
            // Head turned 90 deg to the right (facing Unity +x); accelerating along +x is forward for the head.
            var f = HeadAxes.SpecificForceFromLinear(new Vector3(1, 0, 0), Quaternion.Euler(new Vector3(0, 90, 0)));
            Assert.That(f.x, Is.EqualTo(1f).Within(1e-4f));
            Assert.That(f.y, Is.EqualTo(0f).Within(1e-4f));
            // Accelerating towards Unity +z (the head's left when facing +x) is positive lateral.
            f = HeadAxes.SpecificForceFromLinear(new Vector3(0, 0, 1), Quaternion.Euler(new Vector3(0, 90, 0)));
            Assert.That(f.y, Is.EqualTo(1f).Within(1e-4f));
        }

        [Test]
        public void SpecificForceMagnitudeIsIndependentOfHeadTilt()
        {
            var linear = new Vector3(0.3f, 1.5f, -0.4f);
            float expected = Magnitude(linear + new Vector3(0, G, 0));
            var f = HeadAxes.SpecificForceFromLinear(linear, Quaternion.Euler(new Vector3(-20, 40, 10)));
            Assert.That(Magnitude(f), Is.EqualTo(expected).Within(1e-3f));
        }

        static float Magnitude(Vector3 v) => (float)System.Math.Sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    }
}
