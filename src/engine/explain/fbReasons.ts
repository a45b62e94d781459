// Why a standard timer's or counter's output is what it is, read from its pins after the scan
// (the same pins the generated code wrote): `ET 1.2 s of PT 3 s; IN went TRUE at scan 4,210`.
import type { Value } from '../../model/iecTypes';
import type { ScanView } from './view';
import { seconds } from './words';

export interface FbContext {
  readonly view: ScanView;
  /** Adds a "changed at scan N" link for the name and returns that scan. */
  changeLink(name: string, label?: string): number | undefined;
}

const num = (v: Value | undefined): number => (v === undefined ? NaN : Number(v));
const bool = (v: Value | undefined): boolean => v === true;

function since(c: FbContext, name: string, value: boolean): string {
  const at = c.changeLink(name, `${name} went ${value ? 'TRUE' : 'FALSE'}`);
  return at === undefined ? '' : `; ${name.slice(name.indexOf('.') + 1)} went ${value ? 'TRUE' : 'FALSE'} at scan ${at.toLocaleString('en-US')}`;
}

/** The reason for `instance.pin` of a standard FB type, or undefined for other blocks and pins. */
export function fbReason(c: FbContext, instance: string, type: string, pin: string): string | undefined {
  const v = (p: string) => c.view.value(`${instance}.${p}`);
  const t = type.toUpperCase();
  if (t === 'TON' || t === 'TOF' || t === 'TP') {
    const inOn = bool(v('IN'));
    const et = num(v('ET'));
    const pt = num(v('PT'));
    const q = bool(v('Q'));
    const timing = `ET ${seconds(et)} of PT ${seconds(pt)}`;
    const inText = `IN is ${inOn ? 'TRUE' : 'FALSE'}${since(c, `${instance}.IN`, inOn)}`;
    if (t === 'TON')
      return inOn
        ? q
          ? `${timing}: IN has been TRUE for PT; ${inText}`
          : `${timing}: Q goes TRUE when IN has been TRUE for PT; ${inText}`
        : `IN is FALSE, so the timer is reset (${timing})${since(c, `${instance}.IN`, false)}`;
    if (t === 'TOF')
      return inOn
        ? `Q follows IN while IN is TRUE; ${inText}`
        : q
          ? `${timing}: Q stays TRUE for PT after IN goes FALSE; ${inText}`
          : `${timing}: IN has been FALSE for PT; ${inText}`;
    return q ? `${timing}: the pulse lasts PT from the rising edge of IN; ${inText}` : `${timing}: a pulse starts at a rising edge of IN; ${inText}`;
  }
  if (/^CTU(_|$)/.test(t) || /^CTD(_|$)/.test(t) || /^CTUD(_|$)/.test(t)) {
    const cv = num(v('CV'));
    const pv = num(v('PV'));
    const parts: string[] = [];
    if (t.startsWith('CTUD')) {
      if (pin === 'QU') parts.push(`QU is CV >= PV: CV ${cv} of PV ${pv}`);
      else if (pin === 'QD') parts.push(`QD is CV <= 0: CV ${cv}`);
      else parts.push(`CV ${cv} of PV ${pv}`);
    } else if (t.startsWith('CTU')) parts.push(`Q is CV >= PV: CV ${cv} of PV ${pv}`);
    else parts.push(`Q is CV <= 0: CV ${cv} (counting down from PV ${pv})`);
    const cvAt = c.changeLink(`${instance}.CV`, `${instance}.CV became ${cv}`);
    if (cvAt !== undefined) parts.push(`CV last changed at scan ${cvAt.toLocaleString('en-US')}`);
    return parts.join('; ');
  }
  if (t === 'R_TRIG' || t === 'F_TRIG') {
    const clk = bool(v('CLK'));
    return `Q is TRUE for one scan when CLK goes ${t === 'R_TRIG' ? 'TRUE' : 'FALSE'}; CLK is ${clk ? 'TRUE' : 'FALSE'}${since(c, `${instance}.CLK`, clk)}`;
  }
  if (t === 'SR' || t === 'RS') {
    const s = bool(v(t === 'SR' ? 'S1' : 'S'));
    const r = bool(v(t === 'SR' ? 'R' : 'R1'));
    return `${t === 'SR' ? 'set wins' : 'reset wins'}: S is ${s ? 'TRUE' : 'FALSE'}, R is ${r ? 'TRUE' : 'FALSE'}`;
  }
  return undefined;
}
