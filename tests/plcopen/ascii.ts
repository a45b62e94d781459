// ASCII drawing of a network grid, for readable test failures and debugging.
import { boxLayout } from '../../src/model/boxLayout';
import type { Network } from '../../src/model/project';

export function ascii(net: Network): string {
  const W = 6;
  const lines: string[][] = Array.from({ length: net.rows * 2 }, () =>
    Array.from({ length: net.cols * W + 1 }, () => ' '),
  );
  const put = (r: number, x: number, s: string) => {
    for (let i = 0; i < s.length; i++) if (lines[r]![x + i] !== undefined) lines[r]![x + i] = s[i]!;
  };
  for (let r = 0; r < net.rows; r++) {
    put(r * 2, 0, '|');
    put(r * 2, net.cols * W, '|');
  }
  for (const v of net.vlinks) {
    put(v.row * 2, v.boundary * W, '+');
    put(v.row * 2 + 1, v.boundary * W, '|');
    put(v.row * 2 + 2, v.boundary * W, '+');
  }
  for (const el of net.elements) {
    const x = el.col * W + 1;
    const y = el.row * 2;
    switch (el.kind) {
      case 'link':
        put(y, x, '-----');
        break;
      case 'contact':
        put(y, x, `[${el.contact === 'NO' ? ' ' : el.contact[0]}]${el.variable.slice(0, 2)}`);
        break;
      case 'coil':
        put(y, x, `(${el.coil[0]})${el.variable.slice(0, 2)}`);
        break;
      case 'jump':
        put(y, x, `>>${el.target.slice(0, 3)}`);
        break;
      case 'return':
        put(y, x, '<RET>');
        break;
      case 'connector':
        put(y, x, `>${el.name.slice(0, 3)}>`);
        break;
      case 'continuation':
        put(y, x, `>${el.name.slice(0, 3)}>`);
        break;
      case 'box': {
        const l = boxLayout(el);
        put(y, x, `[${el.blockType}`.slice(0, 11));
        if (l) for (let i = 1; i < l.rows; i++) put(y + i * 2, x, '[');
        if (l) for (const p of l.inputs) put(y + p.rowOffset * 2 + 1, x, p.name.slice(0, 3));
        break;
      }
    }
  }
  return lines.map((l) => l.join('').trimEnd()).join('\n');
}
