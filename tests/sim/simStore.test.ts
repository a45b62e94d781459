import { describe, expect, test } from 'vitest';
import { EXAMPLES } from '../../src/model/examples';
import type { Project } from '../../src/model/project';
import { createSimStore } from '../../src/store/simStore';
import { liveText } from '../../src/editor/sim/liveValues';
import { elementLiveText } from '../../src/editor/sim/useNetworkSim';
import { loopback } from './loopback';
import { brokenProgram, motorProgram, threeNetworks } from './programs';

const example = (id: string): Project => EXAMPLES.find((e) => e.id === id)!.build();

function setup() {
  const { transport, scheduler } = loopback();
  const store = createSimStore(transport);
  return { store, scheduler, s: () => store.getState() };
}

describe('the simulation store', () => {
  test('Run with a broken document keeps the mode and lists the errors with their rule ids', () => {
    const { s } = setup();
    s().run(brokenProgram());
    expect(s().mode).toBe('stopped');
    expect(s().refusal?.online).toBe(false);
    expect(s().refusal?.diagnostics.map((d) => d.rule)).toContain('LD-R08');
  });

  test('the motor example: toggling Start from the inputs seals the motor in; values show as IEC text', () => {
    const { s, scheduler } = setup();
    s().run(example('motor-start-stop'));
    scheduler.advance(50);
    expect(s().mode).toBe('running');
    expect(s().live).toBe(true);
    s().toggleInput('Start');
    scheduler.advance(50);
    expect(liveText(s(), 'Motor')).toBe('TRUE');
    s().toggleInput('Start');
    scheduler.advance(50);
    expect(liveText(s(), 'Start')).toBe('FALSE');
    expect(liveText(s(), 'Motor')).toBe('TRUE');
    s().pressInput('Stop');
    scheduler.advance(50);
    s().releaseInput('Stop');
    scheduler.advance(50);
    expect(liveText(s(), 'Motor')).toBe('FALSE');
  });

  test('the coil shows its live state under it, with forced values marked', () => {
    const { s, scheduler } = setup();
    const project = motorProgram();
    s().run(project);
    s().force('Motor', { value: true });
    scheduler.advance(30);
    const motorCoil = project.pous[0]!.networks[0]!.elements.find((e) => e.kind === 'coil')!;
    expect(elementLiveText(s(), motorCoil)).toBe('TRUE [F]');
    s().unforceAll();
    scheduler.advance(30);
    expect(elementLiveText(s(), motorCoil)).toBe('TRUE');
  });

  test('breakpoints are kept by network, so they follow the network when the program is reloaded', () => {
    const { s, scheduler } = setup();
    const project = threeNetworks();
    const third = project.pous[0]!.networks[2]!.id;
    s().toggleBreakpoint(third);
    s().run(project);
    scheduler.advance(30);
    expect(s().mode).toBe('paused');
    expect(s().breakpointHit).toBe(2);
    s().toggleBreakpoint(third);
    s().run(project);
    scheduler.advance(30);
    expect(s().mode).toBe('running');
  });

  test('the trend window keeps the last N scans of each chosen signal', () => {
    const { s, scheduler } = setup();
    s().setTrendCapacity(20);
    s().step(motorProgram(), 1);
    scheduler.advance(1000);
    s().toggleTrend('Motor');
    s().toggleTrend('Start');
    // Step N runs in slices of wall time: on a busy machine the 50 scans take more than one.
    s().step(motorProgram(), 50);
    scheduler.advance(1000);
    expect(s().trend.names).toEqual(['Motor', 'Start']);
    expect(s().trend.scans).toHaveLength(20);
    expect(s().trend.scans.at(-1)).toBe(51);
    expect(s().trend.series[0]).toHaveLength(20);
  });

  test('the gateway seam: outputs are delivered to subscribers and inputs come in by address', () => {
    const { s, scheduler } = setup();
    const seen: boolean[] = [];
    const stop = s().onOutputs((outputs) => seen.push(outputs['%QX0.0'] === true));
    s().run(motorProgram());
    scheduler.advance(30);
    s().setInputs({ '%IX0.0': true });
    scheduler.advance(30);
    expect(seen.at(-1)).toBe(true);
    stop();
    s().setInputs({ '%IX0.1': true });
    const before = seen.length;
    scheduler.advance(30);
    expect(seen).toHaveLength(before);
  });

  test('an edit while running is applied online; the status names the refusal when it does not compile', () => {
    const { s, scheduler } = setup();
    s().run(motorProgram());
    scheduler.advance(30);
    s().documentChanged(brokenProgram());
    expect(s().refusal?.online).toBe(true);
    expect(s().mode).toBe('running');
    s().documentChanged(threeNetworks());
    scheduler.advance(30);
    expect(s().refusal).toBeUndefined();
    expect(s().layout?.networkIds).toHaveLength(3);
  });
});

describe('opening another project', () => {
  test('unload stops the simulation, drops forces and breakpoints, and the next Run compiles the new document', () => {
    const { s, scheduler } = setup();
    const first = threeNetworks();
    s().toggleBreakpoint(first.pous[0]!.networks[1]!.id);
    s().run(first);
    s().force('Motor', { value: true });
    scheduler.advance(30);
    s().unload();
    scheduler.advance(30);
    expect(s()).toMatchObject({ mode: 'stopped', scan: 0, live: false, layout: undefined, breakpoints: [] });
    expect(s().forced.size).toBe(0);
    s().run(motorProgram());
    scheduler.advance(30);
    expect(s().mode).toBe('running');
    expect(s().layout?.networkIds).toHaveLength(1);
  });

  test('a request the simulator cannot answer is answered with why: Why? on a scan no longer recorded, a trace of unknown names', async () => {
    const { s, scheduler } = setup();
    s().run(example('motor-start-stop'));
    scheduler.advance(50);
    s().explain({ kind: 'variable', name: 'Motor' }, 999_999);
    // Said where the question was asked (the Why? panel), not left waiting.
    await expect.poll(() => s().historyMessage).toBe('scan 999999 is not in the history');
    await expect(s().exportHistory({ format: 'trace', names: ['NoSuchVariable'] })).rejects.toThrow(/NoSuchVariable/);
    // The simulation goes on.
    scheduler.advance(50);
    expect(s().mode).toBe('running');
  });
});

