// Stand-in for the parts of Sentis (package com.unity.ai.inference 2.x, namespace Unity.InferenceEngine, Unity 6) that
// Runtime/Sentis uses. Signatures follow the package sources as published in the read-only mirror
// github.com/needle-mirror/com.unity.ai.inference (commit 9ed8efd8d1b27a47dbcdf634fca222a0b3041ebe, package 2.x; file
// named beside each type). Only the members the package calls are here. Behaviour is only what tests need: a Worker
// runs the function its Model carries (standInRun, set by tests; no such member exists in Sentis) instead of a network.
using System;
using System.Collections.Generic;

namespace Unity.InferenceEngine
{
    // Runtime/Core/InferenceEngine.cs: public enum BackendType { GPUCompute = 0 | DeviceType.GPU, GPUPixel = 1 | DeviceType.GPU, CPU = 0 | DeviceType.CPU }
    public enum BackendType
    {
        GPUCompute = 0 | (1 << 8),
        GPUPixel = 1 | (1 << 8),
        CPU = 0 | (1 << 9),
    }

    // Runtime/Core/Internals/ModelAsset.cs: public class ModelAsset : ScriptableObject (the importer's output for an .onnx file).
    public class ModelAsset : UnityEngine.ScriptableObject
    {
        internal Model standInModel; // stand-in only: what ModelLoader.Load returns
    }

    // Runtime/Core/Serialization/ModelLoader.cs: public static class ModelLoader { public static Model Load(ModelAsset modelAsset) }
    public static class ModelLoader
    {
        public static Model Load(ModelAsset modelAsset) => modelAsset.standInModel;
    }

    // Runtime/Core/Model.cs: public class Model { public struct Input { name; index; dataType; DynamicTensorShape shape }
    // public struct Output { name; index } public List<Input> inputs; public List<Output> outputs; }
    public class Model
    {
        public struct Input
        {
            public string name;
            public int index;
            public DynamicTensorShape shape;
        }

        public struct Output
        {
            public string name;
            public int index;
        }

        public List<Input> inputs = new List<Input>();
        public List<Output> outputs = new List<Output>();

        // Stand-in only: computes a Worker's outputs by name from its input.
        internal Func<Tensor<float>, Dictionary<string, Tensor<float>>> standInRun;
        internal int standInWorkersAlive;
    }

    // Runtime/Core/ShapeInference/DynamicTensorShape.cs: public unsafe struct DynamicTensorShape with public
    // DynamicTensorShape(int d0, int d1, int d2) (-1 = dynamic), bool isRankDynamic, int rank, int Get(int axis) (-1 when dynamic).
    public struct DynamicTensorShape
    {
        readonly int[] dims;

        public DynamicTensorShape(int d0, int d1, int d2) => dims = new[] { d0, d1, d2 };
        public DynamicTensorShape(int d0, int d1) => dims = new[] { d0, d1 };

        public bool isRankDynamic => dims == null;
        public int rank => dims.Length;
        public int Get(int axis) => dims[axis < 0 ? dims.Length + axis : axis];
    }

    // Runtime/Core/TensorShape.cs: public unsafe struct TensorShape with public TensorShape(int d0, int d1, int d2),
    // TensorShape(int d0, int d1), int rank, int length, int this[int axis] { get; set; }.
    public struct TensorShape
    {
        readonly int[] dims;

        public TensorShape(int d0, int d1, int d2) => dims = new[] { d0, d1, d2 };
        public TensorShape(int d0, int d1) => dims = new[] { d0, d1 };

        public int rank => dims.Length;

        public int length
        {
            get
            {
                int n = 1;
                foreach (var d in dims) n *= d;
                return n;
            }
        }

        public int this[int axis]
        {
            get => dims[axis < 0 ? dims.Length + axis : axis];
            set => dims[axis < 0 ? dims.Length + axis : axis] = value;
        }

        public override string ToString() => "(" + string.Join(", ", dims) + ")";
    }

    // Runtime/Core/Tensor.cs: public abstract class Tensor : IDisposable { TensorShape shape { get; } void Dispose(); internal bool disposed; }
    public abstract class Tensor : IDisposable
    {
        private protected TensorShape m_Shape;
        private protected bool m_Disposed;

        public TensorShape shape => m_Shape;
        internal bool disposed => m_Disposed;

        public void Dispose() => m_Disposed = true;
    }

    // Runtime/Core/TensorGeneric.cs: public class Tensor<T> : Tensor where T : unmanaged, with
    // public Tensor(TensorShape shape, T[] srcData, int dataStartIndex = 0) and public T[] DownloadToArray() (blocking copy).
    public class Tensor<T> : Tensor where T : unmanaged
    {
        readonly T[] data;

        public Tensor(TensorShape shape, T[] srcData, int dataStartIndex = 0)
        {
            if (srcData.Length - dataStartIndex < shape.length) throw new ArgumentException("RangeError: array too small for the shape");
            m_Shape = shape;
            data = new T[shape.length];
            Array.Copy(srcData, dataStartIndex, data, 0, data.Length);
        }

        public T[] DownloadToArray()
        {
            if (m_Disposed) throw new ObjectDisposedException("Tensor");
            return (T[])data.Clone();
        }
    }

    // Runtime/Core/Backends/Worker.cs: public class Worker : IDisposable { public Worker(Model model, BackendType backendType);
    // public void SetInput(string name, Tensor input); public void Schedule(); public Tensor PeekOutput(string name); public void Dispose(); }
    // PeekOutput's tensor belongs to the worker (valid until the next Schedule or Dispose).
    public class Worker : IDisposable
    {
        readonly Model model;
        Tensor input;
        Dictionary<string, Tensor<float>> outputs;
        bool disposed;

        public Worker(Model model, BackendType backendType)
        {
            this.model = model ?? throw new ArgumentNullException(nameof(model));
            model.standInWorkersAlive++;
        }

        public void SetInput(string name, Tensor input)
        {
            if (!model.inputs.Exists(i => i.name == name)) throw new ArgumentException($"Cannot set input tensor {name} as model does not contain an input with that name");
            this.input = input;
        }

        public void Schedule()
        {
            if (disposed) throw new ObjectDisposedException(nameof(Worker));
            if (outputs != null) foreach (var o in outputs.Values) o.Dispose();
            outputs = model.standInRun((Tensor<float>)input);
        }

        public Tensor PeekOutput(string name)
        {
            if (outputs == null || !outputs.TryGetValue(name, out var t)) throw new ArgumentException($"Cannot peek output tensor {name} as model does not contain an output with that name");
            return t;
        }

        public void Dispose()
        {
            if (disposed) return;
            disposed = true;
            model.standInWorkersAlive--;
            if (outputs != null) foreach (var o in outputs.Values) o.Dispose();
        }
    }
}
