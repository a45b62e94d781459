import { expect, test } from 'vitest';
import type { ElementId } from '../../src/model/ids';
import { clipText, parseClip } from '../../src/store/clipboard';

test('a clip survives the trip through clipboard text', () => {
  const text = clipText({
    elements: [{ kind: 'contact', contact: 'NO', variable: 'Start', id: 'e1' as ElementId, row: 0, col: 0 }],
    vlinks: [{ row: 0, boundary: 1 }],
  });
  expect(text).toContain('rungsmith-clip');
  const clip = parseClip(text);
  expect(clip?.elements).toHaveLength(1);
  expect(clip?.vlinks).toEqual([{ row: 0, boundary: 1 }]);
});

test('text that is not a clip, or a clip with broken elements, is refused', () => {
  expect(parseClip('hello')).toBeUndefined();
  expect(parseClip('{"format":"other"}')).toBeUndefined();
  const broken = JSON.stringify({
    format: 'rungsmith-clip',
    version: 1,
    elements: [{ kind: 'contact', id: 'x', row: 0, col: 0 }],
    vlinks: [],
  });
  expect(parseClip(broken)).toBeUndefined();
});
