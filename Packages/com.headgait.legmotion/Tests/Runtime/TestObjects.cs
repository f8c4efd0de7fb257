using System.Collections.Generic;
using UnityEngine;

namespace HeadGait.Tests
{
    /// <summary>
    /// The GameObjects a Play Mode test makes, destroyed in its [TearDown] so none outlives the test into the next one
    /// (Object.Destroy: gone when the frame ends).
    /// </summary>
    public sealed class TestObjects
    {
        readonly List<GameObject> made = new List<GameObject>();

        public GameObject New(string name)
        {
            var go = new GameObject(name);
            made.Add(go);
            return go;
        }

        public void DestroyAll()
        {
            foreach (var go in made) Object.Destroy(go);
            made.Clear();
        }
    }
}
