// Typed counters (MATIEC lib/counter.txt: CTU_DINT, CTU_LINT, CTU_UDINT, CTU_ULINT and the CTD/CTUD
// equivalents): the body of CTU/CTD/CTUD with PV and CV of the type in the name. MATIEC counts up
// while CV < PV and down while CV > 0 for every type (profile openplc); the iec profile counts to
// the limits of CV's type, so CV never wraps.
import { describe, expect, it } from 'vitest';
import { createFb, type FbInstance } from '../../src/engine/library/fbs';
import { blockSignature, FB_SIGNATURES } from '../../src/model/blocks';
import type { Value } from '../../src/model/iecTypes';
import { ALL_BLOCKS } from '../../src/editor/palette/paletteItems';
import { ladder, plcOf, project, vars } from './ladder';

const TYPES = ['DINT', 'LINT', 'UDINT', 'ULINT'] as const;
const big = (t: string) => t === 'LINT' || t === 'ULINT';
/** `n` in the representation of type `t` (bigint for 64-bit types). */
const val = (t: string, n: number | bigint): Value => (big(t) ? BigInt(n) : Number(n));

function pulse(fb: FbInstance, pin: string, n: number): void {
  for (let i = 0; i < n; i++) {
    fb.set(pin, true);
    fb.execute(0);
    fb.set(pin, false);
    fb.execute(0);
  }
}

describe('signatures', () => {
  it.each(TYPES)('CTU_%s, CTD_%s, CTUD_%s have PV and CV of their type, in the palette', (t) => {
    for (const base of ['CTU', 'CTD', 'CTUD']) {
      const name = `${base}_${t}`;
      const sig = blockSignature(name)!;
      const std = blockSignature(base)!;
      expect(sig.kind).toBe('fb');
      expect(sig.category).toBe('counter');
      expect(sig.inputs.map((p) => p.name)).toEqual(std.inputs.map((p) => p.name));
      expect(sig.outputs.map((p) => p.name)).toEqual(std.outputs.map((p) => p.name));
      expect(sig.inputs.find((p) => p.name === 'PV')!.type).toBe(t);
      expect(sig.outputs.find((p) => p.name === 'CV')!.type).toBe(t);
      expect(FB_SIGNATURES).toContain(sig);
      expect(ALL_BLOCKS).toContain(sig);
      expect(blockSignature(name.toLowerCase())).toBe(sig);
    }
  });
});

describe.each(TYPES)('%s counters', (t) => {
  it('openplc: CTU counts edges up to PV (CV < PV), R resets', () => {
    const c = createFb(`CTU_${t}`, 'openplc')!;
    expect(c.fbType).toBe(`CTU_${t}`);
    c.set('PV', 3);
    expect(c.get('PV')).toEqual(val(t, 3));
    pulse(c, 'CU', 5);
    expect([c.get('CV'), c.get('Q')]).toEqual([val(t, 3), true]);
    c.set('R', true);
    c.execute(0);
    expect([c.get('CV'), c.get('Q')]).toEqual([val(t, 0), false]);
  });

  it('iec: CTU counts past PV and stops at the maximum of its type', () => {
    const c = createFb(`CTU_${t}`, 'iec')!;
    c.set('PV', 3);
    pulse(c, 'CU', 5);
    expect(c.get('CV')).toEqual(val(t, 5));
    const max = {
      DINT: 2147483647n,
      LINT: 9223372036854775807n,
      UDINT: 4294967295n,
      ULINT: 18446744073709551615n,
    }[t];
    c.set('CV', val(t, max - 1n));
    pulse(c, 'CU', 3);
    expect(c.get('CV')).toEqual(val(t, max));
  });

  it('CTD: LD loads PV, counts down to 0 (openplc) or the type minimum (iec); Q = CV <= 0', () => {
    for (const profile of ['openplc', 'iec'] as const) {
      const c = createFb(`CTD_${t}`, profile)!;
      c.set('PV', 2);
      c.set('LD', true);
      c.execute(0);
      expect([c.get('CV'), c.get('Q')]).toEqual([val(t, 2), false]);
      c.set('LD', false);
      pulse(c, 'CD', 4);
      const signed = t === 'DINT' || t === 'LINT';
      expect([c.get('CV'), c.get('Q')]).toEqual([val(t, profile === 'iec' && signed ? -2 : 0), true]);
    }
  });

  it('CTUD: R wins over LD, simultaneous edges cancel, QU/QD', () => {
    const c = createFb(`CTUD_${t}`, 'openplc')!;
    c.set('PV', 2);
    pulse(c, 'CU', 1);
    expect([c.get('CV'), c.get('QU'), c.get('QD')]).toEqual([val(t, 1), false, false]);
    c.set('CU', true);
    c.set('CD', true);
    c.execute(0);
    expect(c.get('CV')).toEqual(val(t, 1));
    c.set('CU', false);
    c.set('CD', false);
    c.execute(0);
    pulse(c, 'CU', 3);
    expect([c.get('CV'), c.get('QU')]).toEqual([val(t, 2), true]);
    c.set('LD', true);
    c.set('R', true);
    c.execute(0);
    expect([c.get('CV'), c.get('QD')]).toEqual([val(t, 0), true]);
    c.set('R', false);
    c.execute(0);
    expect(c.get('CV')).toEqual(val(t, 2));
  });

  it('state survives saveState/loadState exactly (JSON safe) and reset clears it', () => {
    const c = createFb(`CTUD_${t}`, 'iec')!;
    const v = { DINT: -5n, LINT: -(1n << 60n) - 3n, UDINT: 4000000000n, ULINT: (1n << 63n) + 7n }[t];
    c.set('CV', val(t, v));
    c.set('PV', val(t, v));
    const state = JSON.parse(JSON.stringify(c.saveState(0))) as ReturnType<FbInstance['saveState']>;
    const d = createFb(`CTUD_${t}`, 'iec')!;
    d.loadState(state, 0);
    expect([d.get('CV'), d.get('PV')]).toEqual([val(t, v), val(t, v)]);
    d.reset();
    expect(d.get('CV')).toEqual(val(t, 0));
  });
});

describe('in a ladder program', () => {
  it('CTU_DINT with PV beyond INT and a DINT CV; CTUD_ULINT with a ULINT CV', () => {
    const p = project(
      vars(
        'Pulse BOOL',
        'Down BOOL',
        'C1 CTU_DINT',
        'C2 CTUD_ULINT',
        'Count DINT',
        'Big ULINT',
        'Full BOOL',
        'Up BOOL',
      ),
      [
        ladder(['[Pulse] # # (Full)', '. # # .', '. # # .'], {
          boxes: [
            {
              row: 0,
              col: 1,
              type: 'CTU_DINT',
              instance: 'C1',
              inputs: { R: 'FALSE', PV: '100000' },
              outputs: { CV: 'Count' },
            },
          ],
        }),
        ladder(['[Pulse] # # (Up)', '[Down] # # .', '. # # .', '. # # .', '. # # .'], {
          boxes: [
            {
              row: 0,
              col: 1,
              type: 'CTUD_ULINT',
              instance: 'C2',
              inputs: { R: 'FALSE', LD: 'FALSE', PV: '2' },
              outputs: { CV: 'Big' },
            },
          ],
        }),
      ],
    );
    const plc = plcOf(p, 10, 'openplc');
    for (let i = 0; i < 3; i++) {
      plc.write('Pulse', true);
      plc.scan();
      plc.write('Pulse', false);
      plc.scan();
    }
    expect([plc.read('Count'), plc.read('Full'), plc.read('Big'), plc.read('Up')]).toEqual([
      3,
      false,
      2n,
      true,
    ]);
    plc.write('Down', true);
    plc.scan();
    expect(plc.read('Big')).toBe(1n);
  });
});
