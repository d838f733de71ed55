// Runs WGSL jobs through Dawn's node binding (npm `webgpu`, pinned in package.json), whose WGSL
// compiler is Tint: what Chrome and Edge compile a renderer's shaders with.
//   node tests/dawn/run.mjs --probe      prints the adapter, exits 1 when Dawn finds none
//   node tests/dawn/run.mjs DIR [FROM]   runs DIR/jobs.tsv from job FROM (default 0), appending
//                                        to DIR/results.txt (+ out files)
// jobs.tsv, one job a line, tab-separated: name, source file, then for a dispatch (else "-"):
// entry, uniform words (comma-separated), column files (comma-separated, or "-"), output words,
// workgroups "x,y" — the harness's Dispatch (src/harness/mod.rs): bind group 0 = uniform, the
// column buffers in order, the output buffer last; columns and outputs are little-endian files
// in DIR. A job with no dispatch may name a fourth column: a JSON file of pipeline descriptors
// (WebGPU's, less module and layout: the job's module, "auto") to create, which runs Tint's
// backend; without it only Tint's front end judges the module. results.txt: "adapter TEXT" once per start, then per job "msg I TYPE LINE:COL TEXT",
// "err I TEXT", "out I FILE" and last "job I ok|error MS" (texts on one line; MS the job's
// milliseconds). Each job's lines are appended together once the job is done, "job" last, so a
// process that dies mid-run leaves every finished job readable and the caller (tests/common/
// dawn.rs) starts a new one FROM the first job without a "job" line.
import { create, globals } from 'webgpu';
import fs from 'node:fs';
import path from 'node:path';

Object.assign(globalThis, globals);
const gpu = create(['backend=vulkan']);
const adapter = await gpu.requestAdapter();
if (!adapter) {
  console.error('dawn: no adapter (Dawn needs a Vulkan 1.1 driver with shaderUniform*ArrayDynamicIndexing; ' +
    'on Debian bookworm run `bash .ci/setup-dawn`, which unpacks Mesa 25 lavapipe beside the system one)');
  process.exit(1);
}
const info = adapter.info;
const describe = `${info.description || info.device || 'adapter'} [${info.vendor}, ${info.architecture}, ${info.device}]`;
if (process.argv[2] === '--probe') {
  console.log(describe);
  process.exit(0);
}
const dir = process.argv[2];
const from = Number(process.argv[3] || 0);
// Injected faults, for the test of the caller's supervision only: PREPASS_DAWN_FAULTS
// "crash:I,hang:J" aborts at job I / blocks (no CPU, as Dawn's deadlock does) at job J, each only
// in a process that started before that job.
const faults = Object.fromEntries((process.env.PREPASS_DAWN_FAULTS || '').split(',').filter(f => f)
  .map(f => f.split(':')).map(([kind, at]) => [kind, Number(at)]));
const results = path.join(dir, 'results.txt');
const device = await adapter.requestDevice();
// Dawn's instance lives as long as the JS objects `gpu` and `adapter`, and the device does not
// keep it alive: once neither is reachable, V8 may collect them mid-run and free the instance
// that the binding still polls (InstanceBase::ProcessEvents), which crashed (SIGSEGV, SIGABRT in
// CallbackTaskManager::Flush) or deadlocked the runner after a couple of hundred jobs. Hold them.
globalThis.prepassDawnRoots = [gpu, adapter];
const jobs = fs.readFileSync(path.join(dir, 'jobs.tsv'), 'utf8').split('\n').filter(l => l).map(l => {
  const [name, file, entry, uniform, columns, outWords, groups] = l.split('\t');
  const job = { name, source: fs.readFileSync(path.join(dir, file), 'utf8') };
  if (entry === '-' && uniform) job.pipelines = JSON.parse(fs.readFileSync(path.join(dir, uniform), 'utf8'));
  if (entry && entry !== '-') {
    Object.assign(job, {
      entry,
      uniform: uniform.split(',').map(Number),
      columns: columns === '-' ? [] : columns.split(','),
      outWords: Number(outWords),
      groups: groups.split(',').map(Number),
    });
  }
  return job;
});
// Creates each pipeline (Tint's backend runs here, not at createShaderModule) and returns the
// first error with the pipeline it came from, or null. Both scopes: Dawn reports a backend
// failure as an internal error, a limit or interface mismatch as a validation error.
async function buildPipelines(module, descriptors) {
  for (const [k, d] of descriptors.entries()) {
    const desc = { label: `pipeline ${k}`, ...d, layout: 'auto' };
    for (const stage of ['compute', 'vertex', 'fragment']) {
      if (d[stage]) desc[stage] = { ...d[stage], module };
    }
    const stages = ['compute', 'vertex', 'fragment'].filter(t => d[t]).map(t => `${t} ${d[t].entryPoint}`);
    device.pushErrorScope('internal');
    device.pushErrorScope('validation');
    let thrown = null;
    try {
      if (desc.compute) device.createComputePipeline(desc);
      else device.createRenderPipeline(desc);
    } catch (e) {
      thrown = e; // a descriptor the binding cannot convert (a bad enum value, say)
    }
    const errs = [await device.popErrorScope(), await device.popErrorScope(), thrown].filter(e => e);
    if (errs.length) return `${desc.label} (${stages.join(', ')}): ${errs.map(e => e.message).join('; ')}`;
  }
  return null;
}
const oneLine = t => String(t).replace(/\s+/g, ' ').trim();
fs.appendFileSync(results, `adapter ${oneLine(describe)}\n`);
for (const [i, job] of jobs.entries()) {
  if (i < from) continue;
  if (faults.crash === i && from < i) process.abort();
  if (faults.hang === i && from < i) Atomics.wait(new Int32Array(new SharedArrayBuffer(4)), 0, 0);
  const started = performance.now();
  const r = { name: job.name, messages: [], error: null, out: null };
  device.pushErrorScope('validation');
  const module = device.createShaderModule({ code: job.source, label: job.name });
  const compiled = await module.getCompilationInfo();
  r.messages = compiled.messages.map(m => ({ type: m.type, line: m.lineNum, col: m.linePos, message: m.message }));
  let err = await device.popErrorScope();
  if (err) {
    r.error = err.message;
  } else if (job.pipelines) {
    r.error = await buildPipelines(module, job.pipelines);
  } else if (job.entry) {
    device.pushErrorScope('validation');
    const pipeline = device.createComputePipeline({ layout: 'auto', compute: { module, entryPoint: job.entry } });
    const storage = (bytes, usage) => {
      const b = device.createBuffer({ size: Math.max(16, Math.ceil(bytes.byteLength / 16) * 16), usage: usage | GPUBufferUsage.COPY_DST });
      device.queue.writeBuffer(b, 0, bytes);
      return b;
    };
    const entries = [{ binding: 0, resource: { buffer: storage(new Uint32Array(job.uniform), GPUBufferUsage.UNIFORM) } }];
    for (const c of job.columns) {
      const bytes = fs.readFileSync(path.join(dir, c));
      entries.push({ binding: entries.length, resource: { buffer: storage(new Uint8Array(bytes), GPUBufferUsage.STORAGE) } });
    }
    const outBytes = Math.max(16, job.outWords * 4);
    const out = device.createBuffer({ size: outBytes, usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC });
    entries.push({ binding: entries.length, resource: { buffer: out } });
    const read = device.createBuffer({ size: outBytes, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });
    const bindGroup = device.createBindGroup({ layout: pipeline.getBindGroupLayout(0), entries });
    const encoder = device.createCommandEncoder();
    const pass = encoder.beginComputePass();
    pass.setPipeline(pipeline);
    pass.setBindGroup(0, bindGroup);
    pass.dispatchWorkgroups(job.groups[0], job.groups[1]);
    pass.end();
    encoder.copyBufferToBuffer(out, 0, read, 0, outBytes);
    device.queue.submit([encoder.finish()]);
    err = await device.popErrorScope();
    if (err) {
      r.error = err.message;
    } else {
      await read.mapAsync(GPUMapMode.READ);
      const words = new Uint8Array(read.getMappedRange().slice(0, job.outWords * 4));
      r.out = `out${i}.bin`;
      fs.writeFileSync(path.join(dir, r.out), words);
      read.unmap();
    }
  }
  const lines = [];
  for (const m of r.messages) lines.push(`msg ${i} ${m.type} ${m.line}:${m.col} ${oneLine(m.message)}`);
  if (r.error) lines.push(`err ${i} ${oneLine(r.error)}`);
  if (r.out) lines.push(`out ${i} ${r.out}`);
  lines.push(`job ${i} ${r.error ? 'error' : 'ok'} ${Math.round(performance.now() - started)}`);
  fs.appendFileSync(results, lines.join('\n') + '\n');
}
process.exit(0);
