// The centre view of a POU written in ST: one line saying what it is and how the keys work, then
// the ST editor of its body. The declarations are edited in the variables panel (table or text),
// as for an LD POU.
import { useMemo } from 'react';
import type { Pou } from '../../model/project';
import { KIND_TITLES } from '../project/pouWords';
import type { StEditorContext } from './context';
import { StEditor } from './StEditor';

export function StBodyView({ pou }: { readonly pou: Pou }) {
  const ctx = useMemo<StEditorContext>(() => ({ pouId: pou.id }), [pou.id]);
  return (
    <section className="rs-st-body" aria-label={`ST body of ${pou.name}`} data-testid="st-body-view">
      <p className="rs-st-note" id={`st-note-${pou.id}`}>
        <strong>{pou.name}</strong> ({KIND_TITLES[pou.kind].toLowerCase()}
        {pou.kind === 'FUNCTION' && pou.returnType ? ` : ${pou.returnType}` : ''}, ST). Tab indents; Esc then Tab
        leaves the editor; Ctrl+F finds; Ctrl+Z undoes in the project&apos;s history.
      </p>
      <StEditor ctx={ctx} />
    </section>
  );
}
