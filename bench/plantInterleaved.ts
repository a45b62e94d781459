// Why a moving machine costs more in the scan than alone (issue 26, docs/benchmarks.md, "sixth
// pass"): the tank's loop (PlantLoop.afterScan, the tank filling and draining under a two-point
// controller, an I/O image of plain arrays) timed alone, then with other code run between its
// steps, as a program's scan runs between them in the simulator. The other code is N small
// functions of integer arithmetic, each its own compiled code (a scan of a 100-network program is
// the engine's compiled code for each network); the machine's own work is the same in every row.
//
//   npx tsx bench/plantInterleaved.ts        (prints ns per step for N = 0, 5, 10, 20, 40)
import { PlantLoop } from '../src/plant/loop';
import { tank } from '../src/plant/tank';
import type { Value } from '../src/model/iecTypes';

const STEPS = 200_000;
const ROUNDS = 7;

function machine(): { step: (k: number) => void } {
  const inputs: Value[] = [false, false, false, false, 0];
  const outputs: Value[] = [false, false, false, false];
  const addrIn = ['%IX0.0', '%IX0.1', '%IX0.2', '%IX0.3', '%IW0'];
  const addrOut = ['%QX0.0', '%QX0.1', '%QX0.2', '%QX0.3'];
  const image = {
    inputs,
    outputs,
    input: (a: string) => addrIn.indexOf(a),
    output: (a: string) => addrOut.indexOf(a),
    write: (i: number, v: Value) => {
      inputs[i] = v;
    },
  };
  const loop = new PlantLoop(tank, {});
  loop.bind({ outputs: () => ({}), setInputs: () => {}, ioImage: () => image });
  loop.setOperator('Start', true);
  let filling = false;
  return {
    step: (k) => {
      // The reference solution's two-point control, on the switches the tank presented.
      const low = inputs[2] === true;
      if (!low) filling = true;
      if (inputs[3] === true) filling = false;
      outputs[0] = filling;
      outputs[1] = filling;
      outputs[2] = low;
      outputs[3] = true;
      loop.afterScan(k, (k - 1) * 10, 10);
    },
  };
}

function others(n: number): () => void {
  const fns: ((x: number) => number)[] = [];
  for (let i = 0; i < n; i++) {
    const body = Array.from({ length: 12 }, (_, j) => `x = (x * ${i + j + 3} + ${j}) | 0; if (x > ${1000 + i}) x -= ${i + 7};`).join('\n');
    fns.push(new Function('x', `"use strict";\n${body}\nreturn x;`) as (x: number) => number);
  }
  let sink = 0;
  return () => {
    let x = sink;
    for (let i = 0; i < fns.length; i++) x = fns[i]!(x);
    sink = x;
  };
}

const median = (xs: number[]): number => [...xs].sort((a, b) => a - b)[xs.length >> 1]!;

for (const n of [0, 5, 10, 20, 40]) {
  const m = machine();
  const between = others(n);
  let k = 1;
  const block = (withMachine: boolean): number => {
    const t0 = performance.now();
    for (let i = 0; i < STEPS; i++, k++) {
      between();
      if (withMachine) m.step(k);
    }
    return ((performance.now() - t0) / STEPS) * 1e6;
  };
  block(true);
  block(false);
  const cost: number[] = [];
  const alone: number[] = [];
  for (let r = 0; r < ROUNDS; r++) {
    const w = block(true);
    const b = block(false);
    cost.push(w - b);
    alone.push(b);
  }
  console.log(`${String(n).padStart(2)} functions between steps (${median(alone).toFixed(0)} ns): the machine ${median(cost).toFixed(0)} ns per step`);
}
