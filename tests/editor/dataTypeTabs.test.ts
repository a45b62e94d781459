// Data types open as tabs beside the POUs: opening shows the type, opening a POU shows the POU,
// a rename moves the tab, a new project closes them; each editor has its own tabs.
import { expect, test } from 'vitest';
import { newProject } from '../../src/model/factory';
import { createDocumentStore } from '../../src/store/documentStore';
import { dataTypeTabs } from '../../src/editor/dataTypes/dataTypeTabs';

test('a data type tab shows the type until a POU is opened; rename and close follow', () => {
  const doc = createDocumentStore(newProject('P'));
  const tabs = dataTypeTabs(doc);
  const t = () => tabs.getState();
  doc.getState().addDataType('struct', 'Point');
  t().openType('Point');
  t().openType('point');
  expect(t()).toMatchObject({ open: ['Point'], shown: 'point' });
  const fb = doc.getState().addPou('FUNCTION_BLOCK', 'Motor')!;
  expect(doc.getState().activePouId).toBe(fb);
  expect(t().shown).toBeUndefined();
  t().openType('Point');
  t().renamed('Point', 'Coord');
  expect(t()).toMatchObject({ open: ['Coord'], shown: 'Coord' });
  t().closeType('Coord');
  expect(t()).toMatchObject({ open: [], shown: undefined });
  t().openType('Coord');
  doc.getState().newProject('Q');
  expect(t()).toMatchObject({ open: [], shown: undefined });
  expect(dataTypeTabs(createDocumentStore(newProject('R'))).getState().open).toEqual([]);
  expect(dataTypeTabs(doc)).toBe(tabs);
});
