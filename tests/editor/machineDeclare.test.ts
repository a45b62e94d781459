// Declaring a name on the canvas with a machine chosen (issue 26): the machine's point is offered
// at the machine's address first, and the next free address skips the machine's wires.
import { describe, expect, test } from 'vitest';
import { declareChoices, machinePointOffers } from '../../src/editor/inspector/declareOffer';
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
    expect(first!.variable).toMatchObject({
      name: 'lowlevel',
      type: 'BOOL',
      location: '%IX0.2',
      comment: 'Low level float switch, ON at 200 L and above',
    });
    expect(declareChoices(tankProject(), 'Pump', coil)[0]!.label).toBe(
      "BOOL output at %QX0.0, the machine's Pump",
    );
  });
  test('at its rewired address; not offered when a variable has that address already, or for another type', () => {
    expect(declareChoices(tankProject([], { Pump: '%QX1.0' }), 'Pump', coil)[0]!.variable.location).toBe(
      '%QX1.0',
    );
    const taken = declareChoices(tankProject([['Feed', 'BOOL', { location: '%QX0.0' }]]), 'Pump', coil);
    expect(taken.map((c) => c.label)).not.toContain("BOOL output at %QX0.0, the machine's Pump");
    expect(
      declareChoices(tankProject(), 'Level', { kind: 'pin', direction: 'input', pinType: 'ANY_NUM' })[0]!
        .label,
    ).toBe("INT input at %IW0, the machine's Level");
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

describe("the machine's points while a name is typed", () => {
  const main = (p: Project) => p.pous[0]!;
  test('the undeclared points starting with it, of the type the place takes, at their addresses', () => {
    const project = tankProject([['HighLevel', 'BOOL', { location: '%IX0.3' }]]);
    const offers = (typed: string, role: Parameters<typeof machinePointOffers>[2]) =>
      machinePointOffers(project, typed, role, main(project)).map((c) => c.label);
    expect(offers('L', contact)).toEqual(["BOOL input at %IX0.2, the machine's LowLevel"]);
    // HighLevel is declared already; the name typed whole is declareChoices' own offer.
    expect(offers('Hi', contact)).toEqual([]);
    expect(offers('Level', { kind: 'pin', direction: 'input', pinType: 'ANY_NUM' })).toEqual([]);
    expect(offers('Lev', { kind: 'pin', direction: 'input', pinType: 'ANY_NUM' })).toEqual([
      "INT input at %IW0, the machine's Level",
    ]);
    expect(offers('', contact)).toEqual([]);
    expect(offers('P', coil)).toEqual(["BOOL output at %QX0.0, the machine's Pump"]);
  });
  test('not in a function block, nor without a machine', () => {
    const fb = { kind: 'FUNCTION_BLOCK' as const, variables: [] };
    expect(machinePointOffers(tankProject(), 'L', contact, fb)).toEqual([]);
    const none = newProject('p', { pous: [newPou('Main')] });
    expect(machinePointOffers(none, 'L', contact, none.pous[0]!)).toEqual([]);
  });
});
