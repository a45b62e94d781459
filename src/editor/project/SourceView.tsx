// A POU in another language than LD (ST, IL, FBD, SFC from a PLCopen file): its source, read-only.
import { bodyLanguage, libraryInfo } from '../../model/codesysUtil';
import type { Pou } from '../../model/project';

export function SourceView({ pou }: { readonly pou: Pou }) {
  const language = bodyLanguage(pou);
  const library = libraryInfo(pou);
  return (
    <section className="rs-source-view" aria-label={`Source of ${pou.name}`} data-testid="source-view">
      <p className="rs-source-note" role="note">
        {library
          ? `${pou.name} is a block of the ${library.vendor} ${library.library} library, which the file calls without declaring it: the import added it in ${language}, written from ${library.vendor}'s documented behaviour. The simulator runs it; it is read-only and not exported (${library.vendor} brings its own).`
          : `${pou.name} is written in ${language}. ${
              pou.language === 'FBD'
                ? `${language} bodies are not run (LD-E51): this body is shown read-only and kept as written.`
                : `The simulator runs this ${language} body as written; the editor edits LD only, so it is shown read-only and kept as written.`
            }`}{' '}
        LD networks call {pou.name} through its interface.
      </p>
      <pre className="rs-source-text rs-mono" tabIndex={0}>
        {pou.source ?? '(no source text)'}
      </pre>
    </section>
  );
}
