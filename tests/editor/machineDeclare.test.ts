// Declaring a name on the canvas with a machine chosen (issue 26): the machine's point is offered
// at the machine's address first, and the next free address skips the machine's wires.
import { describe, expect, test } from 'vitest';
import { declareChoices } from '../../src/editor/inspector/declareOffer';
import { nextFreeAddress } from '../../src/editor/variables/addresses';
import { newPou, newProject, variable } from '../../src/model/factory';
import type { Project } from '../../src/model/project';

const tankProject = (vars: Parameters<typeof variable>[] = [], map?: Record<string, string>): Project =>
  newProject('p', {
    pous: [newPou('Main', { variables: vars.map((v) => variable(...v)) })],
    plant: { id: 'tank', ...(map ? { map } : {}) },
  });
const contact = { kind: 'contact' } as const;
const coil = { kind: 'coil' } as const;

describe("a machine's point typed on a contact or coil", () => {
  test('is offered first at the address the machine has it, with its comment, whatever the case typed', () => {
    const [first] = declareChoices(tankProject(), 'lowlevel', contact);
    expect(first!.label).toBe("BOOL input at %IX0.2, the machine's LowLevel");
    expect(first!.variable).toMatchObject({ name: 'lowlevel', type: 'BOOL', location: '%IX0.2', comment: 'Low level float switch, ON at 200 L and above' });
    expect(declareChoices(tankProject(), 'Pump', coil)[0]!.label).toBe("BOOL output at %QX0.0, the machine's Pump");
  });
  test('at its rewired address; not offered when a variable has that address already, or for another type', () => {
    expect(declareChoices(tankProject([], { Pump: '%QX1.0' }), 'Pump', coil)[0]!.variable.location).toBe('%QX1.0');
    const taken = declareChoices(tankProject([['Feed', 'BOOL', { location: '%QX0.0' }]]), 'Pump', coil);
    expect(taken.map((c) => c.label)).not.toContain("BOOL output at %QX0.0, the machine's Pump");
    expect(declareChoices(tankProject(), 'Level', { kind: 'pin', direction: 'input', pinType: 'ANY_NUM' })[0]!.label).toBe(
      "INT input at %IW0, the machine's Level",
    );
    expect(declareChoices(tankProject(), 'Level', contact)[0]!.label).toBe('BOOL');
  });
  test('a name that is no point of the machine gets no such offer; without a machine nothing changes', () => {
    expect(declareChoices(tankProject(), 'Running', coil)[0]!.label).toBe('BOOL');
    const none = newProject('p', { pous: [newPou('Main')] });
    expect(declareChoices(none, 'LowLevel', contact)[0]!.label).toBe('BOOL');
  });
});

describe('the next free address with a machine chosen', () => {
  test("skips the machine's wires, as rewired: a new input does not read its Start button, a new output does not drive its pump", () => {
    expect(nextFreeAddress(tankProject(), 'I', 'BOOL')).toBe('%IX0.4');
    expect(nextFreeAddress(tankProject(), 'Q', 'BOOL')).toBe('%QX0.4');
    expect(nextFreeAddress(tankProject(), 'I', 'INT')).toBe('%IW1');
    expect(nextFreeAddress(tankProject([], { Start: '%IX0.4' }), 'I', 'BOOL')).toBe('%IX0.0');
    expect(nextFreeAddress(tankProject(), 'M', 'BOOL')).toBe('%MX0.0');
  });
});
