// Online change as the UI sees it (store + session over the loopback transport): the parts counter
// keeps its count through an edit, the confirmation names what was kept and reset, and with the
// hardware attached as controller the edit waits for Apply or Cancel.
import { describe, expect, test } from 'vitest';
import { EXAMPLES } from '../../src/model/examples';
import { variable } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { createSimStore } from '../../src/store/simStore';
import { ladder } from '../engine/ladder';
import { loopback } from './loopback';

const partsCounter = (): Project => EXAMPLES.find((e) => e.id === 'parts-counter')!.build();

/** The same project with one more network (a timer T3 and a lamp), edited while it runs. */
function withTimerNetwork(p: Project): Project {
  const main = p.pous[0]!;
  const t3 = ladder(['[PartSensor] # # - (Lamp)', '. # # . .'], { boxes: [{ row: 0, col: 1, type: 'TON', instance: 'T3', inputs: { PT: 'T#1s' } }] });
  return {
    ...p,
    pous: [{ ...main, variables: [...main.variables, variable('T3', 'TON'), variable('Lamp', 'BOOL')], networks: [...main.networks, t3] }],
  };
}

function setup() {
  const { transport, scheduler } = loopback();
  const store = createSimStore(transport);
  const s = () => store.getState();
  const value = (name: string) => s().values[s().variableIndex.get(name.toUpperCase())!];
  const pulses = (n: number) => {
    for (let i = 0; i < n; i++) {
      s().write('PartSensor', { value: true });
      scheduler.advance(30);
      s().write('PartSensor', { value: false });
      scheduler.advance(30);
    }
  };
  return { s, scheduler, value, pulses };
}

describe('online change in the store', () => {
  test('the parts counter keeps its count through an edit; the notice says when and what was kept and reset', () => {
    const { s, scheduler, value, pulses } = setup();
    const doc = partsCounter();
    s().run(doc);
    pulses(4);
    expect(value('PartCount')).toBe(4);
    s().documentChanged(withTimerNetwork(doc));
    scheduler.advance(60);
    expect(s().layout?.networkIds).toHaveLength(2);
    expect(value('Parts.CV')).toBe(4);
    expect(value('PartCount')).toBe(4);
    const change = s().onlineChange;
    expect(change?.kind).toBe('applied');
    if (change?.kind !== 'applied') return;
    expect(change.plan).toEqual({ kept: 1, reset: [{ name: 'T3', reason: 'new' }], removed: [] });
    expect(change.scan).toBeGreaterThan(0);
    pulses(1);
    expect(value('PartCount')).toBe(5);
    // A cold restart resets everything the change kept: its confirmation goes away.
    s().reset();
    scheduler.advance(30);
    expect(s().onlineChange).toBeUndefined();
  });

  test('with the hardware attached as controller, Cancel leaves the running program as it was and Apply puts the edit in', () => {
    const { s, scheduler, value, pulses } = setup();
    const doc = partsCounter();
    s().setOnlineConfirmRequired(true);
    s().run(doc);
    pulses(2);
    const edited = withTimerNetwork(doc);
    s().documentChanged(edited);
    scheduler.advance(60);
    expect(s().onlineChange).toMatchObject({ kind: 'confirm', plan: { reset: [{ name: 'T3', reason: 'new' }] } });
    expect(s().layout?.networkIds).toHaveLength(1);
    s().answerOnlineChange(false);
    scheduler.advance(60);
    expect(s().onlineChange?.kind).toBe('cancelled');
    expect(s().layout?.networkIds).toHaveLength(1);
    expect(s().mode).toBe('running');
    pulses(1);
    expect(value('PartCount')).toBe(3);

    const again: Project = { ...edited, pous: [{ ...edited.pous[0]!, networks: [...edited.pous[0]!.networks] }] };
    s().documentChanged({ ...again, name: 'edited again' });
    scheduler.advance(60);
    expect(s().onlineChange?.kind).toBe('confirm');
    s().answerOnlineChange(true);
    scheduler.advance(60);
    expect(s().onlineChange?.kind).toBe('applied');
    expect(s().layout?.networkIds).toHaveLength(2);
    expect(value('PartCount')).toBe(3);
  });
});
