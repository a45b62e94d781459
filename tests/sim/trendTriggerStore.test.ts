// The trend trigger through the simulation store and the worker (loopback): arming, the capture
// shown, prepared values written (Ctrl+F7) and forced (F7) from the watch table.
import { describe, expect, test } from 'vitest';
import { createSimStore } from '../../src/store/simStore';
import { forcePrepared, preparedMessage, preparedValues, writePrepared } from '../../src/editor/sim/preparedValues';
import { liveText } from '../../src/editor/sim/liveValues';
import { loopback } from './loopback';
import { motorProgram } from './programs';

function setup() {
  const { transport, scheduler } = loopback();
  const store = createSimStore(transport);
  return { store, scheduler, s: () => store.getState() };
}

describe('trend trigger in the store', () => {
  test('armed, triggered by a pulse of Start, the capture kept; Arm again drops it and waits', () => {
    const { s, scheduler } = setup();
    s().toggleTrend('Start');
    s().toggleTrend('Motor');
    s().setTrendCapacity(20);
    s().setTrendTrigger({ name: 'Start', direction: 'rising', level: 0.5, prePercent: 20, mode: 'single' });
    expect(s().trendTriggerState).toBe('armed');
    s().run(motorProgram());
    scheduler.advance(100);
    s().pressInput('Start');
    scheduler.advance(10);
    s().releaseInput('Start');
    scheduler.advance(400);
    expect(s().trendTriggerState).toBe('done');
    const capture = s().trendCapture!;
    expect(capture.triggerIndex).toBe(4);
    expect(capture.samples.scans).toHaveLength(20);
    expect(capture.samples.series[capture.samples.names.indexOf('Start')]![4]).toBe(1);
    expect(capture.samples.series[capture.samples.names.indexOf('Start')]![3]).toBe(0);
    s().armTrendTrigger();
    expect(s().trendCapture).toBeUndefined();
    scheduler.advance(100);
    expect(s().trendTriggerState).toBe('armed');
    expect(s().trendCapture).toBeUndefined();
    s().setTrendTrigger(undefined);
    scheduler.advance(50);
    expect(s().trendTriggerState).toBeUndefined();
  });
});

describe('prepared values', () => {
  test('Ctrl+F7 writes every prepared value once and clears them; F7 forces; a field input is kept with the reason', () => {
    const { s, scheduler, store } = setup();
    s().run(motorProgram());
    scheduler.advance(50);
    preparedValues.getState().clear();
    preparedValues.getState().prepare({ name: 'Motor', text: 'TRUE', input: { text: 'TRUE' } });
    const wrote = writePrepared(store);
    expect(wrote.done).toEqual(['Motor']);
    expect(preparedValues.getState().values.size).toBe(0);
    scheduler.advance(50);
    expect(liveText(s(), 'Motor')).toBe('TRUE');
    preparedValues.getState().prepare({ name: 'Stop', text: 'TRUE', input: { text: 'TRUE' } });
    preparedValues.getState().prepare({ name: 'Start', text: 'TRUE', input: { text: 'TRUE' }, field: '%IX0.0' });
    const forced = forcePrepared(store);
    expect(forced.done).toEqual(['Stop']);
    expect(forced.kept.map((k) => k.name)).toEqual(['Start']);
    expect(preparedMessage('Forced', forced)).toMatch(/^Forced Stop\. Start not forced: .*%IX0\.0.*Force on hardware/);
    scheduler.advance(50);
    expect(s().forced.get('STOP')).toBe(true);
    expect(liveText(s(), 'Motor')).toBe('FALSE');
    expect(preparedValues.getState().values.size).toBe(1);
    preparedValues.getState().clear();
    expect(preparedMessage('Wrote', writePrepared(store))).toMatch(/No prepared values/);
  });

  test('a prepared value the variable cannot hold ("abc" for an INT, 2 for a BOOL) is neither written nor forced: it stays prepared with the reason', () => {
    const { s, scheduler, store } = setup();
    s().run(motorProgram());
    scheduler.advance(50);
    preparedValues.getState().clear();
    preparedValues.getState().prepare({ name: 'Motor', text: '2', input: { text: '2' } });
    preparedValues.getState().prepare({ name: 'Stop', text: 'TRUE', input: { text: 'TRUE' } });
    const wrote = writePrepared(store);
    expect(wrote.done).toEqual(['Stop']);
    expect(preparedMessage('Wrote', wrote)).toBe('Wrote Stop. Motor not written: 2 is an integer, not a BOOL (use TRUE, FALSE, 1 or 0).');
    expect([...preparedValues.getState().values.values()].map((v) => v.text)).toEqual(['2']);
    const forced = forcePrepared(store);
    expect(forced.done).toEqual([]);
    expect(forced.kept.map((k) => k.name)).toEqual(['Motor']);
    scheduler.advance(50);
    expect(s().forced.size).toBe(0);
    expect(liveText(s(), 'Motor')).toBe('FALSE');
    preparedValues.getState().clear();
  });
});
