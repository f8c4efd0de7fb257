// Runs the exported ONNX models with ONNX Runtime (npm onnxruntime-node) on the reference windows saved at training
// time and compares them with the training framework's outputs. Usage: node check_onnx.mjs MODEL_FOLDER
// Prints one line per model and exits 1 on a mismatch, 2 when there is nothing to check.
import { readFileSync, existsSync } from 'node:fs';
import { join } from 'node:path';
import * as ort from 'onnxruntime-node';

/** Reads HeadGait's model/reference file format: text header up to "end", then little-endian tensors. */
function readTensors(path) {
  const bytes = readFileSync(path);
  let pos = 0;
  const line = () => {
    const end = bytes.indexOf(0x0a, pos);
    if (end < 0) throw new Error(`${path}: header ends without 'end'`);
    const s = bytes.toString('utf8', pos, end);
    pos = end + 1;
    return s;
  };
  if (line() !== 'headgait-model v1') throw new Error(`${path}: not a HeadGait model file`);
  const specs = [];
  for (let l = line(); l !== 'end'; l = line()) {
    if (!l.startsWith('tensor=')) continue;
    const [name, type, dims] = l.slice(7).split(' ');
    specs.push({ name, f64: type === 'f64', shape: dims.split('x').map(Number) });
  }
  const tensors = {};
  for (const s of specs) {
    const count = s.shape.reduce((a, b) => a * b, 1);
    const size = s.f64 ? 8 : 4;
    const data = new Float64Array(count);
    for (let i = 0; i < count; i++) data[i] = s.f64 ? bytes.readDoubleLE(pos + i * size) : bytes.readFloatLE(pos + i * size);
    pos += count * size;
    tensors[s.name] = { shape: s.shape, data };
  }
  return tensors;
}

const folder = process.argv[2];
if (!folder) { console.error('usage: node check_onnx.mjs MODEL_FOLDER'); process.exit(2); }
let checked = 0, failed = 0;
for (const kind of ['blstm', 'svm']) {
  const onnxPath = join(folder, `${kind}.onnx`), refPath = join(folder, 'Reference~', `${kind}.reference.bytes`);
  if (!existsSync(onnxPath) || !existsSync(refPath)) continue;
  const ref = readTensors(refPath);
  const [rows, t, c] = ref.inputs.shape;
  const session = await ort.InferenceSession.create(onnxPath);
  const input = new ort.Tensor('float32', Float32Array.from(ref.inputs.data), [rows, t, c]);
  const out = await session.run({ window: input });
  const width = ref.outputs.shape[1];
  if (kind === 'blstm') {
    // Both run the same float32 network: probabilities agree to 1e-5.
    let worst = 0;
    for (let i = 0; i < rows * width; i++) worst = Math.max(worst, Math.abs(out.probabilities.data[i] - ref.outputs.data[i]));
    const ok = worst <= 1e-5;
    console.log(`${onnxPath}: ${rows} reference windows, max |probability difference| ${worst.toExponential(2)} ${ok ? 'ok' : 'FAIL (limit 1e-5)'}`);
    if (!ok) failed++;
  } else {
    // scikit-learn decides in float64, the ONNX graph in float32 (Sentis runs float32). A decision value sums thousands
    // of cancelling kernel terms (C = 100), so float32 keeps it to about 1e-4 of the range, not better: agree to 1e-3 of
    // the range, and every reference window must get the same class.
    let worst = 0, range = 0, wrong = 0;
    for (let i = 0; i < rows * width; i++) {
      worst = Math.max(worst, Math.abs(out.decision.data[i] - ref.outputs.data[i]));
      range = Math.max(range, Math.abs(ref.outputs.data[i]));
    }
    const k = out.votes.dims[1];
    for (let r = 0; r < rows; r++) {
      let best = 0;
      for (let j = 1; j < k; j++) if (out.votes.data[r * k + j] > out.votes.data[r * k + best]) best = j;
      if (best !== ref.predictions.data[r]) wrong++;
    }
    const ok = worst <= 1e-3 * Math.max(1, range) && wrong === 0;
    console.log(`${onnxPath}: ${rows} reference windows, max |decision difference| ${worst.toExponential(2)} of range ${range.toFixed(2)}, ${wrong} different classes ${ok ? 'ok' : 'FAIL'}`);
    if (!ok) failed++;
  }
  checked++;
}
if (checked === 0) { console.error(`${folder}: no ONNX model with a reference file`); process.exit(2); }
process.exit(failed ? 1 : 0);
