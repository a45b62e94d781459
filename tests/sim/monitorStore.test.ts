// The store side of monitoring FB instances (issue 11): the shown tab picks the body the canvas
// monitors, operand names are read in the picked instance, and a step into is followed.
import { describe, expect, test } from 'vitest';
import { blockLibrary } from '../../src/model/library';
import { canvasName } from '../../src/editor/sim/liveValues';
import { elementLiveText } from '../../src/editor/sim/useNetworkSim';
import { boxPinTexts } from '../../src/editor/sim/pinLiveValues';
import { createSimStore } from '../../src/store/simStore';
import { loopback } from './loopback';
import { configurationProject, motorProject } from './monitorPrograms';

function setup() {
  const { transport, scheduler } = loopback();
  const store = createSimStore(transport);
  return { store, scheduler, s: () => store.getState() };
}

describe('monitoring the shown POU', () => {
  test("an FB's tab shows its first instance, then the picked one: power and values of that instance", () => {
    const { s, scheduler } = setup();
    const project = motorProject();
    const fb = project.pous.find((p) => p.name === 'Motor')!;
    const runCoil = fb.networks[0]!.elements.find((e) => e.kind === 'coil')!;
    s().run(project);
    scheduler.advance(30);
    s().write('Start1', { value: true });
    scheduler.advance(30);
    s().showPou({ name: 'Motor', kind: 'FUNCTION_BLOCK' });
    scheduler.advance(30);
    expect(s().canvasScope).toMatchObject({ view: { pou: 'Motor', instance: 'Motor1' }, prefix: 'Motor1', choices: ['Motor1', 'Motor2'] });
    expect(s().layout?.view).toEqual({ pou: 'Motor', instance: 'Motor1' });
    expect(s().layout?.networkIds).toEqual(fb.networks.map((n) => n.id));
    expect(canvasName(s(), 'Run')).toBe('Motor1.Run');
    expect(elementLiveText(s(), runCoil)).toBe('TRUE');
    const coilPower = s().elements[s().elementIndex.get(runCoil.id)!]!;
    expect(coilPower & 2).toBe(2);
    s().pickInstance('Motor', 'Motor2');
    scheduler.advance(30);
    expect(s().layout?.view).toEqual({ pou: 'Motor', instance: 'Motor2' });
    expect(elementLiveText(s(), runCoil)).toBe('FALSE');
    expect(s().elements[s().elementIndex.get(runCoil.id)!]! & 2).toBe(0);
    // A call box in Main shows the user FB's pins beside them (the instance's values), with the project's library.
    s().showPou({ name: 'Main', kind: 'PROGRAM' });
    scheduler.advance(30);
    const main = project.pous[0]!.networks[0]!;
    const call = main.elements.find((e) => e.kind === 'box')!;
    expect(elementLiveText(s(), call, blockLibrary(project))).toBeUndefined();
    expect(boxPinTexts(s(), main, call, blockLibrary(project))?.inputs.Stop).toBe('FALSE');
    // A PROGRAM the task does not run is not monitored.
    s().showPou({ name: 'Elsewhere', kind: 'PROGRAM' });
    expect(s().canvasScope).toBeUndefined();
  });

  test('in a configuration the program tab monitors one program instance, its names prefixed', () => {
    const { s, scheduler } = setup();
    s().run(configurationProject());
    scheduler.advance(30);
    s().showPou({ name: 'Main', kind: 'PROGRAM' });
    expect(s().canvasScope).toMatchObject({ prefix: 'Line1', choices: ['Line1', 'Line2'] });
    expect(canvasName(s(), 'Start1')).toBe('Line1.Start1');
    s().pickInstance('Main', 'Line2');
    scheduler.advance(30);
    expect(s().layout?.view).toEqual({ pou: 'Main', instance: 'Line2' });
    expect(canvasName(s(), 'Motor1.Run')).toBe('Line2.Motor1.Run');
    s().showPou({ name: 'Motor', kind: 'FUNCTION_BLOCK' });
    expect(s().canvasScope?.choices).toEqual(['Line1.Motor1', 'Line1.Motor2', 'Line2.Motor1', 'Line2.Motor2']);
  });

  test('a step into is followed: the stop names the body and the instance where execution stands', () => {
    const { s } = setup();
    const project = motorProject();
    const seq = s().stopSeq;
    s().stepNetwork(project, true);
    expect(s().stopSeq).toBe(seq + 1);
    expect(s().stop).toEqual({ pou: 'Motor', instance: 'Motor1', network: 0 });
    expect(s().position.map((f) => f.pou)).toEqual(['Main', 'Motor']);
    s().stepNetwork(project);
    expect(s().stop).toEqual({ pou: 'Motor', instance: 'Motor1', network: 1 });
    s().stepNetwork(project);
    // Out of the body: back in the caller.
    expect(s().stop).toEqual({ pou: 'Main', network: 1 });
  });
});
