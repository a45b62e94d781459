// "What runs is always exactly what is shown" (issue 10), on the worker side (SimSession in Node)
// and through the simulation store: a failed install stops the simulation, says why, and never
// leaves the previous program running; the gateway's unused input points are not bound.
import { describe, expect, test } from 'vitest';
import { EXAMPLES } from '../../src/model/examples';
import type { Project } from '../../src/model/project';
import { realEngine } from '../../src/sim/engineAdapter';
import { programId } from '../../src/sim/programId';
import type { HostMessage } from '../../src/sim/protocol';
import type { SimEngine } from '../../src/sim/simEngine';
import { createSimStore } from '../../src/store/simStore';
import { SimHarness } from './harness';
import { loopback } from './loopback';
import { brokenProgram, motorProgram, threeNetworks, timerProgram } from './programs';

const example = (id: string): Project => EXAMPLES.find((e) => e.id === id)!.build();

/** Every point of the gateway's simulated device as the bridge used to pass it (most unused by a program). */
const everyGatewayInput = (): Record<string, boolean | number> => {
  const image: Record<string, boolean | number> = {};
  for (let bit = 0; bit < 16; bit++) image[`%IX${bit >> 3}.${bit & 7}`] = false;
  for (let w = 0; w < 4; w++) image[`%IW${w}`] = 0;
  return image;
};

/** The real engine, except that installing this document's PLC fails `times` times (for any reason). */
function engineFailingOn(project: Project, times = Infinity): SimEngine {
  const bad = programId(project);
  let compiling = '';
  let failures = 0;
  return {
    compile: (p) => {
      compiling = programId(p);
      return realEngine.compile(p);
    },
    createPlc: (program, options) => {
      if (compiling === bad && failures < times) {
        failures++;
        throw new Error('the input card is broken');
      }
      return realEngine.createPlc(program, options);
    },
    parseValue: realEngine.parseValue,
  };
}

describe('the gateway input image binds only the program’s own inputs', () => {
  test('inputs the program does not declare are not bound and raise no error, on Run and while running', () => {
    const h = new SimHarness().send({ type: 'setInputs', values: { ...everyGatewayInput(), '%IX0.0': true } });
    h.send({ type: 'subscribeOutputs', enabled: true }, { type: 'run', project: motorProgram() }).advance(30);
    expect(h.of('error')).toEqual([]);
    expect(h.frame.mode).toBe('running');
    expect(h.value('Start')).toBe(true);
    h.send({ type: 'setInputs', values: { ...everyGatewayInput(), '%IX0.2': true, '%IW3': 77 } }).advance(30);
    expect(h.of('error')).toEqual([]);
    expect(h.value('Start')).toBe(false);
    expect(h.of('outputs').at(-1)?.outputs['%QX0.0']).toBe(true); // sealed in, then Start released
  });
});

describe('a program that fails to install stops the simulation', () => {
  test('Run of a document whose install fails drops the previous program: stopped, no program, the reason posted', () => {
    const second = threeNetworks();
    const h = new SimHarness(engineFailingOn(second));
    h.send({ type: 'run', project: motorProgram() }, { type: 'write', name: 'Start', input: { value: true } }).advance(30);
    expect(h.value('Motor')).toBe(true);
    h.send({ type: 'pause' }, { type: 'reset' }, { type: 'unload' });
    h.send({ type: 'setInputs', values: { '%IX0.0': true } }, { type: 'run', project: second }).advance(50);
    expect(h.of('error').at(-1)?.message).toMatch(/could not be installed, the simulation is stopped: the input card is broken/);
    expect(h.frame).toMatchObject({ mode: 'stopped', program: null, scan: 0, values: [] });
    // Run again without the document: nothing is loaded, nothing runs.
    h.send({ type: 'run' }).advance(50);
    expect(h.of('error').at(-1)?.message).toMatch(/no program is loaded/);
    expect(h.frame).toMatchObject({ mode: 'stopped', program: null });
  });

  test('Run or Step of a document with errors drops the paused program instead of resuming it', () => {
    const h = new SimHarness().send({ type: 'run', project: motorProgram() }).advance(30);
    h.send({ type: 'pause' }, { type: 'step', scans: 1, project: brokenProgram() });
    expect(h.of('compiled').at(-1)).toMatchObject({ ok: false, online: false });
    expect(h.frame).toMatchObject({ mode: 'stopped', program: null });
    const scans = h.frame.scan;
    h.advance(100);
    expect(h.frame.scan).toBe(scans);
  });

  test('an online edit with errors still keeps the last good program running (the errors are shown)', () => {
    const motor = motorProgram();
    const h = new SimHarness().send({ type: 'run', project: motor }).advance(30);
    h.send({ type: 'load', project: brokenProgram() }).advance(30);
    expect(h.of('compiled').at(-1)).toMatchObject({ ok: false, online: true });
    expect(h.frame).toMatchObject({ mode: 'running', program: programId(motor) });
  });

  test('unload drops the program, its forces and the gateway inputs', () => {
    const h = new SimHarness().send({ type: 'setInputs', values: { '%IX0.0': true } }, { type: 'run', project: motorProgram() }).advance(30);
    h.send({ type: 'force', name: 'Motor', input: { value: true } }, { type: 'unload', epoch: 7 });
    expect(h.frame).toMatchObject({ mode: 'stopped', program: null, forced: [], epoch: 7 });
    h.send({ type: 'run', project: motorProgram() }).advance(30);
    expect(h.value('Start')).toBe(false); // the old link's input image went with the old project
  });

  test('every frame names the program that runs', () => {
    const timer = timerProgram();
    const h = new SimHarness().send({ type: 'run', project: timer, epoch: 3 }).advance(30);
    expect(h.frame).toMatchObject({ program: programId(timer), epoch: 3 });
    expect(h.of('compiled').at(-1)?.program).toBe(programId(timer));
  });
});

describe('the store: what runs is what is shown', () => {
  function setup(engine?: SimEngine) {
    const { transport, scheduler } = loopback(engine);
    const store = createSimStore(transport);
    return { store, scheduler, s: () => store.getState() };
  }

  test('issue 10 case 6: after a failed install the second Run sends the document again and runs the shown program', () => {
    const first = example('motor-start-stop');
    const second = threeNetworks();
    const { s, scheduler, store } = setup(engineFailingOn(second, 1));
    const outputs: Record<string, unknown>[] = [];
    s().onOutputs((o) => outputs.push(o));
    s().run(first);
    s().toggleInput('Start');
    scheduler.advance(50);
    expect(s().mode).toBe('running');
    s().pause();
    s().reset();
    s().unload();
    s().run(second); // install fails: stopped, says why, the old program is gone
    scheduler.advance(50);
    expect(s()).toMatchObject({ mode: 'stopped', live: false, layout: undefined });
    expect(s().notice).toMatch(/could not be installed/);
    outputs.length = 0;
    s().run(second); // sent again (not trusted), installs this time
    scheduler.advance(50);
    expect(s().mode).toBe('running');
    expect(s().layout?.networkIds).toEqual(second.pous[0]!.networks.map((n) => n.id));
    expect(store.getState().values.length).toBeGreaterThan(0);
    expect(outputs.every((o) => o['%QX0.0'] !== true)).toBe(true); // the previous program's Motor never comes back
  });

  test('a Run refused for errors clears the old program from the display', () => {
    const { s, scheduler } = setup();
    s().run(motorProgram());
    scheduler.advance(30);
    s().pause();
    s().run(brokenProgram());
    scheduler.advance(30);
    expect(s()).toMatchObject({ mode: 'stopped', live: false, layout: undefined });
    expect(s().refusal?.online).toBe(false);
  });

  test('opening another project makes the worker drop its program: Run without a document runs nothing', () => {
    const { transport, scheduler } = loopback();
    const sent: string[] = [];
    const store = createSimStore({ ...transport, send: (m) => (sent.push(m.type), transport.send(m)) });
    const s = () => store.getState();
    s().run(motorProgram());
    scheduler.advance(30);
    s().unload();
    expect(sent.at(-1)).toBe('unload');
    expect(s().mode).toBe('stopped');
    s().run(threeNetworks());
    scheduler.advance(30);
    expect(s().layout?.networkIds).toHaveLength(3);
  });

  test('a frame from a program other than the shown one is never shown as running; the worker is told to drop it', async () => {
    const { transport, scheduler } = loopback();
    const sent: string[] = [];
    // Like a real worker, commands sent while the store handles a message arrive later, not re-entrantly.
    let inside = false;
    const store = createSimStore({
      ...transport,
      send: (m: HostMessage) => {
        sent.push(m.type);
        if (inside) queueMicrotask(() => transport.send(m));
        else transport.send(m);
      },
      listen: (l) =>
        transport.listen((m) => {
          inside = true;
          l(m);
          inside = false;
        }),
    });
    const s = () => store.getState();
    s().run(motorProgram());
    scheduler.advance(30);
    // The worker is made to run another program behind the store's back (a stray load).
    transport.send({ type: 'load', project: threeNetworks(), epoch: 1 });
    scheduler.advance(30);
    await Promise.resolve();
    scheduler.advance(30);
    expect(s().mode).toBe('stopped');
    expect(s().live).toBe(false);
    expect(s().notice).toMatch(/program other than the one shown/);
    expect(sent.at(-1)).toBe('unload');
  });
});
