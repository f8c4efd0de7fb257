#!/usr/bin/python3
"""Trains HeadGait's learned gait-phase classifiers (SVM and BLSTM) on windows exported by `headgait train`.

The C# side exports exactly the features its classifiers read (X.npy [N, T, C] float32), the class of each window
(y.npy: a stride segment naming both feet's phases, or Standing; -1 = not a segment), the recording of each window
(file.npy), files.tsv and dataset.txt (feature spec, class names, phase map). This script standardises the channels,
trains, and writes model files in HeadGait's own format (read by the package's C# classifiers), ONNX models for Unity
Sentis, and reference outputs that the package's tests compare the C# forward passes against.

Runs offline with Debian's python3-torch, python3-sklearn, python3-onnx and python3-numpy under /usr/bin/python3.
Seeds and thread counts are fixed, so a run is reproducible on the same machine.
"""
import argparse
import warnings
import json
import os
import struct
import sys
import time

import numpy as np

SEED = 20261122


def log(*a):
    print(*a, flush=True)


# ---------------------------------------------------------------- data

class Dataset:
    def __init__(self, folder):
        self.folder = folder
        meta = {}
        with open(os.path.join(folder, "dataset.txt"), encoding="utf-8") as f:
            for line in f:
                k, _, v = line.rstrip("\n").partition("=")
                meta[k] = v
        self.meta = meta
        self.features = meta["features"]
        self.classes = meta["classes"].split(",")
        self.phase_map = meta["phase_map"]
        self.X = np.load(os.path.join(folder, "X.npy"), mmap_mode="r")
        self.y = np.load(os.path.join(folder, "y.npy"))
        self.file = np.load(os.path.join(folder, "file.npy"))
        self.augmented = np.load(os.path.join(folder, "augmented.npy"))
        self.names = {}
        with open(os.path.join(folder, "files.tsv"), encoding="utf-8") as f:
            next(f)
            for line in f:
                i, name, style = line.rstrip("\n").split("\t")
                self.names[int(i)] = name
        if self.X.shape[0] != len(self.y) or len(self.y) != len(self.file):
            raise SystemExit(f"{folder}: X, y and file disagree in length")

    def rows(self, exclude_names=(), starts_and_stops=True):
        """Indices of usable windows (labelled) whose recording is not excluded; with starts_and_stops False, also
        without the copies made into walks that start and stop (augmented == 2)."""
        excluded = np.array([self.names[i] in exclude_names for i in range(len(self.names))])
        keep = (self.y >= 0) & ~excluded[self.file]
        if not starts_and_stops:
            keep &= self.augmented != 2
        return np.where(keep)[0]


def standardisation(X):
    flat = X.reshape(-1, X.shape[2])
    mean = flat.mean(0).astype(np.float64)
    scale = flat.std(0).astype(np.float64) + 1e-6
    return mean, scale


# ---------------------------------------------------------------- model file (HeadGait format)

def write_model(path, values, tensors):
    """values: dict of key -> str; tensors: list of (name, array, 'f32'|'f64')."""
    header = ["headgait-model v1"]
    for k, v in values.items():
        header.append(f"{k}={v}")
    for name, arr, dt in tensors:
        header.append(f"tensor={name} {dt} {'x'.join(str(d) for d in arr.shape)}")
    header.append("end")
    data = "\n".join(header).encode("utf-8") + b"\n"
    for name, arr, dt in tensors:
        a = np.ascontiguousarray(arr, dtype="<f8" if dt == "f64" else "<f4")
        if not np.all(np.isfinite(a)):
            raise SystemExit(f"{path}: tensor {name} has non-finite values")
        data += a.tobytes()
    tmp = path + ".tmp"
    with open(tmp, "wb") as f:
        f.write(data)
    os.replace(tmp, path)


def read_model(path):
    """A HeadGait model file (headgait-model v1): its values and tensors (float64 arrays)."""
    with open(path, "rb") as f:
        data = f.read()
    values, specs = {}, []
    pos = 0
    while True:
        end = data.index(b"\n", pos)
        line = data[pos:end].decode("utf-8")
        pos = end + 1
        if line == "end":
            break
        if line.startswith("tensor="):
            name, dt, shape = line[len("tensor="):].split(" ")
            specs.append((name, dt, tuple(int(d) for d in shape.split("x"))))
        elif "=" in line:
            k, _, v = line.partition("=")
            values[k] = v
    tensors = {}
    for name, dt, shape in specs:
        width = 8 if dt == "f64" else 4
        count = int(np.prod(shape))
        tensors[name] = np.frombuffer(data, dtype="<f8" if dt == "f64" else "<f4", count=count, offset=pos).reshape(shape).astype(np.float64)
        pos += width * count
    return values, tensors


# ---------------------------------------------------------------- BLSTM

def blstm_module(inputs, hidden, classes, dropout):
    import torch
    import torch.nn as nn

    class Blstm(nn.Module):
        """One bidirectional LSTM layer, dropout, a fully connected layer (softmax in the loss / at inference)."""

        def __init__(self):
            super().__init__()
            self.hidden = hidden
            self.lstm = nn.LSTM(inputs, hidden, batch_first=True, bidirectional=True)
            self.dropout = nn.Dropout(dropout)
            self.fc = nn.Linear(2 * hidden, classes)

        def forward(self, x):
            out, _ = self.lstm(x)
            joined = torch.cat([out[:, -1, :self.hidden], out[:, 0, self.hidden:]], dim=1)
            return self.fc(self.dropout(joined))

    return Blstm()


def load_blstm_weights(model, tensors):
    """Sets a module's weights from a HeadGait BLSTM file's tensors (its merged bias goes to bias_ih, bias_hh zero)."""
    import torch
    sd = model.state_dict()
    t = lambda a: torch.tensor(a, dtype=torch.float32)
    sd["lstm.weight_ih_l0"], sd["lstm.weight_ih_l0_reverse"] = t(tensors["lstm_w_ih"][0]), t(tensors["lstm_w_ih"][1])
    sd["lstm.weight_hh_l0"], sd["lstm.weight_hh_l0_reverse"] = t(tensors["lstm_w_hh"][0]), t(tensors["lstm_w_hh"][1])
    sd["lstm.bias_ih_l0"], sd["lstm.bias_ih_l0_reverse"] = t(tensors["lstm_b"][0]), t(tensors["lstm_b"][1])
    sd["lstm.bias_hh_l0"] = torch.zeros_like(sd["lstm.bias_hh_l0"])
    sd["lstm.bias_hh_l0_reverse"] = torch.zeros_like(sd["lstm.bias_hh_l0_reverse"])
    sd["fc.weight"], sd["fc.bias"] = t(tensors["fc_w"]), t(tensors["fc_b"])
    model.load_state_dict(sd)


def train_blstm(X, y, mean, scale, classes, hidden, dropout, epochs, lr, batch, seed, init=None):
    import torch
    import torch.nn.functional as F
    torch.manual_seed(seed)
    np.random.seed(seed)
    model = blstm_module(X.shape[2], hidden, classes, dropout)
    if init is not None:
        load_blstm_weights(model, init)
    Xt = torch.tensor(((np.asarray(X, dtype=np.float32) - mean) / scale).astype(np.float32))
    yt = torch.tensor(y.astype(np.int64))
    opt = torch.optim.Adam(model.parameters(), lr=lr)
    steps = epochs * ((len(Xt) + batch - 1) // batch)
    sched = torch.optim.lr_scheduler.OneCycleLR(opt, max_lr=lr, total_steps=steps)
    gen = torch.Generator().manual_seed(seed)
    for epoch in range(epochs):
        model.train()
        perm = torch.randperm(len(Xt), generator=gen)
        total = 0.0
        for i in range(0, len(Xt), batch):
            b = perm[i:i + batch]
            opt.zero_grad()
            loss = F.cross_entropy(model(Xt[b]), yt[b])
            loss.backward()
            opt.step()
            sched.step()
            total += loss.item() * len(b)
        log(f"    epoch {epoch + 1}/{epochs} loss {total / len(Xt):.4f}")
    model.eval()
    return model


def blstm_probabilities(model, Xs):
    import torch
    with torch.no_grad():
        out = []
        for i in range(0, len(Xs), 4096):
            out.append(torch.softmax(model(torch.tensor(Xs[i:i + 4096], dtype=torch.float32)), dim=1).numpy())
        return np.concatenate(out) if out else np.zeros((0, 0))


def save_blstm(path, model, ds, mean, scale, provenance):
    sd = {k: v.detach().numpy().astype(np.float64) for k, v in model.state_dict().items()}
    w_ih = np.stack([sd["lstm.weight_ih_l0"], sd["lstm.weight_ih_l0_reverse"]])
    w_hh = np.stack([sd["lstm.weight_hh_l0"], sd["lstm.weight_hh_l0_reverse"]])
    b = np.stack([sd["lstm.bias_ih_l0"] + sd["lstm.bias_hh_l0"], sd["lstm.bias_ih_l0_reverse"] + sd["lstm.bias_hh_l0_reverse"]])
    values = {"kind": "blstm", "features": ds.features, "classes": ",".join(ds.classes), "phase_map": ds.phase_map}
    values.update(provenance)
    write_model(path, values, [
        ("input_mean", mean, "f64"), ("input_scale", scale, "f64"),
        ("lstm_w_ih", w_ih, "f32"), ("lstm_w_hh", w_hh, "f32"), ("lstm_b", b, "f32"),
        ("fc_w", sd["fc.weight"], "f32"), ("fc_b", sd["fc.bias"], "f32")])


def export_blstm_onnx(path, model, timesteps, channels):
    """A single bidirectional ONNX LSTM op (opset 15), input 'window' [batch, T, C] standardised, output 'probabilities'."""
    import torch

    class WithSoftmax(torch.nn.Module):
        def __init__(self, m):
            super().__init__()
            self.m = m

        def forward(self, x):
            return torch.softmax(self.m(x), dim=1)

    dummy = torch.zeros(1, timesteps, channels)
    warnings.filterwarnings("ignore", category=UserWarning)  # torch's notes on LSTM batch sizes and shape inference
    torch.onnx.export(WithSoftmax(model), dummy, path, opset_version=15, input_names=["window"], output_names=["probabilities"],
                      dynamic_axes={"window": {0: "batch"}, "probabilities": {0: "batch"}})
    import onnx
    m = onnx.load(path)
    onnx.checker.check_model(m)
    ops = [n.op_type for n in m.graph.node]
    lstm = [n for n in m.graph.node if n.op_type == "LSTM"]
    if len(lstm) != 1 or [a.s for a in lstm[0].attribute if a.name == "direction"] != [b"bidirectional"]:
        raise SystemExit(f"{path}: expected one bidirectional LSTM op, got {ops}")
    return ops


# ---------------------------------------------------------------- SVM

def train_svm(X, y, C, degree, gamma, coef0, max_windows, seed):
    from sklearn.svm import SVC
    rng = np.random.default_rng(seed)
    if len(X) > max_windows:
        # Keep every class present: sample per class in proportion, at least 200 each where available.
        pick = []
        for k in np.unique(y):
            idx = np.where(y == k)[0]
            n = max(min(len(idx), 200), int(round(max_windows * len(idx) / len(y))))
            pick.append(rng.choice(idx, size=min(n, len(idx)), replace=False))
        pick = np.sort(np.concatenate(pick))
        X, y = X[pick], y[pick]
    flat = X.reshape(len(X), -1).astype(np.float64)
    svm = SVC(kernel="poly", degree=degree, C=C, gamma=gamma, coef0=coef0, decision_function_shape="ovo",
              cache_size=2000, random_state=seed)
    svm.fit(flat, y)
    return svm


def svm_arrays(svm, classes):
    """Expands sklearn's per-present-class arrays to all classes (a class absent from training gets no vectors)."""
    present = list(svm.classes_)
    k = len(classes)
    if present != list(range(k)):
        raise SystemExit(f"SVM training data lacks classes {sorted(set(range(k)) - set(present))}; more data is needed")
    return svm.support_vectors_, svm.dual_coef_, svm.intercept_, svm.n_support_


def svm_decision_numpy(sv, dual, intercept, nsup, gamma, coef0, degree, Xflat):
    """The C# classifier's arithmetic, to check it against sklearn before saving."""
    K = (gamma * Xflat @ sv.T + coef0) ** degree
    k = len(nsup)
    start = np.concatenate([[0], np.cumsum(nsup)[:-1]])
    dec = []
    for i in range(k):
        for j in range(i + 1, k):
            si = slice(start[i], start[i] + nsup[i])
            sj = slice(start[j], start[j] + nsup[j])
            dec.append(K[:, si] @ dual[j - 1, si] + K[:, sj] @ dual[i, sj] + intercept[len(dec)])
    return np.stack(dec, 1)


def svm_votes(dec, k):
    votes = np.zeros((len(dec), k))
    p = 0
    for i in range(k):
        for j in range(i + 1, k):
            votes[:, i] += dec[:, p] > 0
            votes[:, j] += dec[:, p] <= 0
            p += 1
    return votes


def save_svm(path, svm, ds, mean, scale, provenance):
    sv, dual, intercept, nsup = svm_arrays(svm, ds.classes)
    values = {"kind": "svm", "features": ds.features, "classes": ",".join(ds.classes), "phase_map": ds.phase_map,
              "gamma": repr(float(svm._gamma)), "coef0": repr(float(svm.coef0)), "degree": str(int(svm.degree)),
              "C": repr(float(svm.C))}
    values.update(provenance)
    write_model(path, values, [
        ("input_mean", mean, "f64"), ("input_scale", scale, "f64"), ("n_support", nsup.astype(np.float64), "f64"),
        ("support_vectors", sv, "f64"), ("dual_coef", dual, "f64"), ("intercept", intercept, "f64")])


def export_svm_onnx(path, svm, k, timesteps, channels):
    """Plain ONNX operators only (Sentis runs no ai.onnx.ml): Reshape, MatMul, Mul, Add, Pow, Greater, Cast, Sub."""
    import onnx
    from onnx import helper, TensorProto, numpy_helper
    sv, dual, intercept, nsup = svm_arrays(svm, list(range(k)))
    d = sv.shape[1]
    n = sv.shape[0]
    pairs = k * (k - 1) // 2
    # Pair decision = kernel @ W + intercept, with W[s, p] the coefficient of vector s in pair p (zero if not its classes).
    W = np.zeros((n, pairs))
    A = np.zeros((pairs, k))  # votes for the first class of a pair when its decision is positive
    B = np.zeros((pairs, k))  # ... for the second class otherwise
    start = np.concatenate([[0], np.cumsum(nsup)[:-1]])
    p = 0
    for i in range(k):
        for j in range(i + 1, k):
            W[start[i]:start[i] + nsup[i], p] = dual[j - 1, start[i]:start[i] + nsup[i]]
            W[start[j]:start[j] + nsup[j], p] = dual[i, start[j]:start[j] + nsup[j]]
            A[p, i] = 1
            B[p, j] = 1
            p += 1
    f32 = lambda a: numpy_helper.from_array(np.asarray(a, dtype=np.float32), name=None)

    def init(name, arr):
        t = f32(arr)
        t.name = name
        return t

    nodes = [
        helper.make_node("Reshape", ["window", "flat_shape"], ["flat"]),
        helper.make_node("MatMul", ["flat", "svT"], ["dot"]),
        helper.make_node("Mul", ["dot", "gamma"], ["scaled"]),
        helper.make_node("Add", ["scaled", "coef0"], ["base"]),
        helper.make_node("Pow", ["base", "degree"], ["kernel"]),
        helper.make_node("MatMul", ["kernel", "W"], ["dec0"]),
        helper.make_node("Add", ["dec0", "intercept"], ["decision"]),
        helper.make_node("Greater", ["decision", "zero"], ["positive"]),
        helper.make_node("Cast", ["positive"], ["pos"], to=TensorProto.FLOAT),
        helper.make_node("Sub", ["one", "pos"], ["neg"]),
        helper.make_node("MatMul", ["pos", "A"], ["va"]),
        helper.make_node("MatMul", ["neg", "B"], ["vb"]),
        helper.make_node("Add", ["va", "vb"], ["votes"]),
    ]
    inits = [numpy_helper.from_array(np.array([-1, d], dtype=np.int64), "flat_shape"),
             init("svT", sv.T), init("gamma", [svm._gamma]), init("coef0", [svm.coef0]), init("degree", [float(svm.degree)]),
             init("W", W), init("intercept", intercept), init("zero", [0.0]), init("one", [1.0]), init("A", A), init("B", B)]
    graph = helper.make_graph(nodes, "headgait_svm",
                              [helper.make_tensor_value_info("window", TensorProto.FLOAT, ["batch", timesteps, channels])],
                              [helper.make_tensor_value_info("votes", TensorProto.FLOAT, ["batch", k]),
                               helper.make_tensor_value_info("decision", TensorProto.FLOAT, ["batch", pairs])],
                              inits)
    model = helper.make_model(graph, opset_imports=[helper.make_opsetid("", 15)], producer_name="headgait")
    onnx.checker.check_model(model)
    onnx.save(model, path)
    return [nd.op_type for nd in nodes]


# ---------------------------------------------------------------- evaluation helper (window level)

def per_foot_error(pred, y, classes):
    """Share of (window, foot) pairs whose phase differs, for class indices."""
    left = np.array([c.split("/")[0] if "/" in c else c for c in classes])
    right = np.array([c.split("/")[1] if "/" in c else c for c in classes])
    return ((left[pred] != left[y]).mean() + (right[pred] != right[y]).mean()) / 2


# ---------------------------------------------------------------- main

def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--data", required=True, help="folder written by `headgait train` (X.npy, y.npy, ...)")
    ap.add_argument("--out", required=True, help="folder for svm.bytes, blstm.bytes, ONNX files and references")
    ap.add_argument("--models", default="svm,blstm")
    ap.add_argument("--exclude", default="", help="file with recording names to leave out (a cross-validation fold's test set)")
    ap.add_argument("--hidden", type=int, default=48)
    ap.add_argument("--dropout", type=float, default=0.4)
    ap.add_argument("--epochs", type=int, default=8)
    ap.add_argument("--lr", type=float, default=3e-3)
    ap.add_argument("--batch", type=int, default=256)
    ap.add_argument("--svm-c", type=float, default=100.0)
    ap.add_argument("--svm-degree", type=int, default=3)
    ap.add_argument("--svm-gamma", default="0.005")
    ap.add_argument("--svm-coef0", type=float, default=1.0)
    ap.add_argument("--svm-windows", type=int, default=12000)
    ap.add_argument("--no-onnx", action="store_true")
    ap.add_argument("--evaluate", action="store_true",
                    help="also score the excluded recordings' windows (per-foot phase error of the classifier output, no animator): a quick check for grid searches")
    ap.add_argument("--blstm-windows", type=int, default=0,
                    help="train the BLSTM on this many windows drawn at random (0: all); with --init, a cheaper fine-tuning")
    ap.add_argument("--init", default="",
                    help="a BLSTM model file to start from (fine-tuning): its weights and its standardisation are kept; --epochs and --lr then set the fine-tuning")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--seed", type=int, default=SEED, help="seeds the SVM's window draw and the BLSTM's initialisation and batches")
    args = ap.parse_args()

    import torch
    torch.set_num_threads(args.threads)
    ds = Dataset(args.data)
    exclude = set()
    if args.exclude:
        with open(args.exclude, encoding="utf-8") as f:
            exclude = {line.strip() for line in f if line.strip()}
    os.makedirs(args.out, exist_ok=True)
    # Reference outputs and the training report are for checks, not for Unity: a '~' folder is not imported.
    refdir = os.path.join(args.out, "Reference~")
    os.makedirs(refdir, exist_ok=True)
    k = len(ds.classes)
    report = {}
    standardised = {}  # model -> its training set's channel mean and scale

    def training_set(starts_and_stops):
        """Windows, classes, standardisation, provenance and reference rows of one model's training set."""
        rows = ds.rows(exclude, starts_and_stops)
        X = np.asarray(ds.X[rows], dtype=np.float32)
        mean, scale = standardisation(X)
        Xs = ((X - mean) / scale).astype(np.float32)
        provenance = {"trained_on": f"{len(np.unique(ds.file[rows]))} recordings, {len(rows)} windows",
                      "trainer": "training/train_learned.py"}
        ref_idx = np.random.default_rng(SEED).choice(len(Xs), size=min(64, len(Xs)), replace=False)
        return X, ds.y[rows], mean, scale, Xs, provenance, ref_idx

    if "blstm" in args.models.split(","):
        # The BLSTM also learns from walks made to start and stop; the SVM gained nothing at starts from them.
        X, y, mean, scale, Xs, provenance, ref_idx = training_set(True)
        T, C = X.shape[1], X.shape[2]
        init, hidden, tuned = None, args.hidden, ""
        if args.init:
            values, init = read_model(args.init)
            if values.get("kind") != "blstm" or values.get("features") != ds.features or values.get("classes") != ",".join(ds.classes):
                raise SystemExit(f"{args.init}: not a BLSTM with this data set's features and classes; cannot fine-tune it")
            # The network learned on its own standardisation; it keeps it.
            mean, scale = init["input_mean"], init["input_scale"]
            Xs = ((X - mean) / scale).astype(np.float32)
            hidden = init["lstm_w_hh"].shape[2]
            tuned = f" fine-tuned from {os.path.basename(args.init)} ({values.get('hyperparameters', '')})"
        if 0 < args.blstm_windows < len(X):
            pick = np.sort(np.random.default_rng(args.seed).choice(len(X), size=args.blstm_windows, replace=False))
            X, y, Xs = X[pick], y[pick], Xs[pick]
            provenance["trained_on"] += f", {len(X)} drawn"
            ref_idx = np.random.default_rng(SEED).choice(len(X), size=min(64, len(X)), replace=False)
        t0 = time.time()
        log(f"BLSTM: hidden {hidden}, dropout {args.dropout}, {args.epochs} epochs, lr {args.lr}, {len(X)} windows of {T}x{C}{tuned}")
        model = train_blstm(X, y, mean, scale, k, hidden, args.dropout, args.epochs, args.lr, args.batch, args.seed, init)
        prov = dict(provenance, hyperparameters=f"hidden={hidden} dropout={args.dropout} epochs={args.epochs} lr={args.lr} batch={args.batch} adam onecycle{tuned}")
        path = os.path.join(args.out, "blstm.bytes")
        save_blstm(path, model, ds, mean, scale, prov)
        probs = blstm_probabilities(model, Xs[ref_idx])
        write_model(os.path.join(refdir, "blstm.reference.bytes"), {"kind": "reference", "model": "blstm.bytes"},
                    [("inputs", Xs[ref_idx].astype(np.float64), "f64"), ("outputs", probs.astype(np.float64), "f64")])
        train_err = per_foot_error(blstm_probabilities(model, Xs[::7]).argmax(1), y[::7], ds.classes)
        standardised["blstm"] = (mean, scale)
        report["blstm"] = {"seconds": round(time.time() - t0), "train_error": round(float(train_err), 4)}
        if not args.no_onnx:
            report["blstm"]["onnx_ops"] = export_blstm_onnx(os.path.join(args.out, "blstm.onnx"), model, T, C)
        log(f"  wrote {path} ({report['blstm']})")

    if "svm" in args.models.split(","):
        X, y, mean, scale, Xs, provenance, ref_idx = training_set(False)
        T, C = X.shape[1], X.shape[2]
        t0 = time.time()
        log(f"SVM: polynomial degree {args.svm_degree}, C {args.svm_c}, gamma {args.svm_gamma}, coef0 {args.svm_coef0}, up to {args.svm_windows} windows")
        gamma = args.svm_gamma if args.svm_gamma in ("scale", "auto") else float(args.svm_gamma)
        svm = train_svm(Xs, y, args.svm_c, args.svm_degree, gamma, args.svm_coef0, args.svm_windows, args.seed)
        sv, dual, intercept, nsup = svm_arrays(svm, ds.classes)
        flat = Xs[ref_idx].reshape(len(ref_idx), -1).astype(np.float64)
        dec = svm_decision_numpy(sv, dual, intercept, nsup, svm._gamma, svm.coef0, svm.degree, flat)
        sk = svm.decision_function(flat)
        if not np.allclose(dec, sk, atol=1e-6, rtol=1e-6):
            raise SystemExit("SVM: the package's decision arithmetic disagrees with scikit-learn's; not saving")
        if not np.array_equal(svm_votes(dec, k).argmax(1), svm.predict(flat)):
            raise SystemExit("SVM: the package's voting disagrees with scikit-learn's predictions; not saving")
        prov = dict(provenance, hyperparameters=f"C={args.svm_c} degree={args.svm_degree} gamma={svm._gamma:.6g} coef0={args.svm_coef0} windows<={args.svm_windows}",
                    support_vectors=str(len(sv)))
        path = os.path.join(args.out, "svm.bytes")
        save_svm(path, svm, ds, mean, scale, prov)
        write_model(os.path.join(refdir, "svm.reference.bytes"), {"kind": "reference", "model": "svm.bytes"},
                    [("inputs", Xs[ref_idx].astype(np.float64), "f64"), ("outputs", sk.astype(np.float64), "f64"),
                     ("predictions", svm.predict(flat).astype(np.float64), "f64")])
        sub = Xs[::29].reshape(len(Xs[::29]), -1).astype(np.float64)
        standardised["svm"] = (mean, scale)
        report["svm"] = {"seconds": round(time.time() - t0), "support_vectors": int(len(sv)),
                         "train_error": round(float(per_foot_error(svm.predict(sub), y[::29], ds.classes)), 4)}
        if not args.no_onnx:
            report["svm"]["onnx_ops"] = export_svm_onnx(os.path.join(args.out, "svm.onnx"), svm, k, T, C)
        log(f"  wrote {path} ({report['svm']})")

    if args.evaluate and exclude:
        held_out = np.array([ds.names[i] in exclude for i in range(len(ds.names))])[ds.file]
        test = np.where((ds.y >= 0) & held_out & (ds.augmented == 0))[0]
        yt = ds.y[test]
        for name, (m, s) in standardised.items():
            Xt = ((np.asarray(ds.X[test], dtype=np.float32) - m) / s).astype(np.float32)
            predicted = blstm_probabilities(model, Xt).argmax(1) if name == "blstm" else svm.predict(Xt.reshape(len(Xt), -1).astype(np.float64))
            report[name]["heldout_error"] = round(float(per_foot_error(predicted, yt, ds.classes)), 4)
        log(f"held-out windows: {len(test)}; " + ", ".join(f"{k} {v['heldout_error']}" for k, v in report.items()))
    # A run that trains one of the models keeps what an earlier run reported of the other.
    path = os.path.join(refdir, "training.json")
    try:
        with open(path, encoding="utf-8") as f:
            earlier = json.load(f)
        earlier = earlier.get("report", {}) if isinstance(earlier, dict) else {}
    except (OSError, ValueError):
        earlier = {}
    earlier.update(report)
    with open(path, "w", encoding="utf-8") as f:
        json.dump({"data": os.path.abspath(args.data), "excluded": len(exclude), "report": earlier}, f, indent=1)


if __name__ == "__main__":
    main()
