// A POU in another language than LD (ST, IL, FBD, SFC from a PLCopen file): its source, read-only.
import type { Pou } from '../../model/project';

export function SourceView({ pou }: { readonly pou: Pou }) {
  return (
    <section className="rs-source-view" aria-label={`Source of ${pou.name}`} data-testid="source-view">
      <p className="rs-source-note" role="note">
        {pou.name} is written in {pou.language}.{' '}
        {pou.language === 'FBD'
          ? 'FBD bodies are not run (LD-E51): this body is shown read-only and kept as written.'
          : `The simulator runs this ${pou.language} body as written; the editor edits LD only, so it is shown read-only and kept as written.`}{' '}
        LD networks call {pou.name} through its interface.
      </p>
      <pre className="rs-source-text rs-mono" tabIndex={0}>
        {pou.source ?? '(no source text)'}
      </pre>
    </section>
  );
}
