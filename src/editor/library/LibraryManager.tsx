// The library manager (File > Libraries…, the Project tree's Libraries section): the libraries
// kept with the project, each with its version (file hash), source file, date and contents; add
// one from a PLCopen XML file or another Rungsmith project (name clashes refused with the reason),
// update it from a newer file (what changes, and which uses need attention, shown first), remove
// it (refused with the list of uses while POUs call its blocks), and view a block read-only.
// OpenPLC's vendor libraries are listed as external blocks (interfaces only, not simulated).
import { useEffect, useMemo, useState } from 'react';
import { useStore } from 'zustand';
import { describeUse, diffLibrary, findLibraryPou, interfaceText, libraryContents, libraryShadows, libraryUses, shortHash, usesOf } from '../../model/libraries';
import { blockLibrary } from '../../model/library';
import type { Pou, ProjectLibrary } from '../../model/project';
import { VENDOR_LIBRARIES } from '../../model/vendorBlocks';
import { selectProject, useDocument, useDocumentStore } from '../../store/documentStore';
import { HiddenFilePicker } from '../files/HiddenFilePicker';
import { ModalDialog } from '../files/ModalDialog';
import { networkSvg } from '../print/networkSvg';
import { canvasMeasure } from '../print/svgContext';
import { readCanvasTheme } from '../theme/canvasTheme';
import { chooseLibraryFile, commitAdd, commitRemove, commitUpdate, readChosenLibrary } from './libraryActions';
import { libraryUi, type PendingLibrary } from './libraryUi';
import './library.css';

/** Mounted once: the hidden file picker and the manager when open. */
export function LibraryHost() {
  const open = useStore(libraryUi, (s) => s.open);
  return (
    <>
      <HiddenFilePicker
        accept=".xml,.json,application/xml,text/xml,application/json"
        label="Library file (PLCopen XML or Rungsmith project)"
        testId="library-file-input"
        register={libraryUi.getState().setOpenPicker}
        onFile={(file) => void readChosenLibrary(file)}
      />
      {open && <LibraryManager />}
    </>
  );
}

const dateText = (iso: string) => {
  const d = new Date(iso);
  return Number.isNaN(d.getTime()) ? iso : d.toISOString().slice(0, 16).replace('T', ' ');
};

function LibraryManager() {
  const store = useDocumentStore();
  const project = useDocument(selectProject);
  const pending = useStore(libraryUi, (s) => s.pending);
  const refused = useStore(libraryUi, (s) => s.refused);
  const viewing = useStore(libraryUi, (s) => s.viewing);
  const close = () => libraryUi.getState().setOpen(false);
  const libraries = project.libraries ?? [];
  const shown = viewing ? findLibraryPou(project, viewing) : undefined;

  return (
    <ModalDialog
      role="dialog"
      titleId="rs-library-title"
      title="Libraries"
      describedBy="rs-library-text"
      className="rs-library-manager"
      testId="library-manager"
      onClose={close}
      buttons={
        <button type="button" className="rs-button rs-primary" data-testid="library-close" onClick={close}>
          Close
        </button>
      }
    >
      <p id="rs-library-text" className="rs-tree-detail">
        A library is a set of function blocks, functions and data types read from a PLCopen XML file or another Rungsmith
        project and kept in this project. Its blocks are called like the project’s own POUs and run in the simulator; they
        are read-only here. Its version is the SHA-256 of the file it was read from.
      </p>
      <div className="rs-library-toolbar">
        <button type="button" className="rs-button" data-testid="library-add" onClick={() => chooseLibraryFile()}>
          Add library…
        </button>
      </div>
      {pending && <PendingPanel pending={pending} />}
      {refused && (
        <div role="alert" className="rs-library-refused" data-testid="library-refused">
          <p className="rs-error-text">
            The library {refused.library} cannot be removed: it is used in {refused.uses.length} place
            {refused.uses.length === 1 ? '' : 's'}. Remove these uses first.
          </p>
          <ul>
            {refused.uses.map((u, i) => (
              <li key={i}>{describeUse(u)}</li>
            ))}
          </ul>
          <button type="button" className="rs-button" onClick={() => libraryUi.getState().setRefused(undefined)}>
            OK
          </button>
        </div>
      )}
      <h3>This project’s libraries</h3>
      {libraries.length === 0 ? (
        <p className="rs-tree-detail" data-testid="library-none">
          None yet. Add the blocks of a PLCopen XML file (CODESYS, Beremiz, OpenPLC, TwinCAT) or of another Rungsmith project.
        </p>
      ) : (
        <table className="rs-library-table" data-testid="library-table">
          <thead>
            <tr>
              <th>Name</th>
              <th>Version</th>
              <th>Source file</th>
              <th>Added</th>
              <th>Contains</th>
              <th>Used</th>
              <th />
            </tr>
          </thead>
          <tbody>
            {libraries.map((lib) => (
              <LibraryRow key={lib.name} lib={lib} uses={libraryUses(project, lib.name).length} onRemove={() => commitRemove(store, lib.name)} />
            ))}
          </tbody>
        </table>
      )}
      {shown && <BlockView library={shown.library} pou={shown.pou} />}
      <h3>OpenPLC vendor libraries (external blocks)</h3>
      <p className="rs-tree-detail">
        Interfaces of the blocks OpenPLC Editor ships. Calls of them run as external blocks: the simulator does not run
        their bodies, their outputs hold their initial values and can be set from the Watch table or a scenario.
      </p>
      <ul className="rs-library-vendor" data-testid="library-vendor">
        {VENDOR_LIBRARIES.map((v) => (
          <li key={v.name} data-testid={`library-vendor-${v.name}`}>
            <details>
              <summary>
                <strong>{v.name}</strong> <span className="rs-tree-detail">({v.file}, {v.blocks.length} function blocks, runs as external block, read-only)</span>
              </summary>
              <ul>
                {v.blocks.map((b) => (
                  <li key={b.name}>
                    <code>{b.name}</code> <span className="rs-tree-detail">{b.comment}</span>
                  </li>
                ))}
              </ul>
            </details>
          </li>
        ))}
      </ul>
    </ModalDialog>
  );
}

function LibraryRow({ lib, uses, onRemove }: { readonly lib: ProjectLibrary; readonly uses: number; readonly onRemove: () => void }) {
  const viewing = useStore(libraryUi, (s) => s.viewing);
  return (
    <tr data-testid={`library-row-${lib.name}`}>
      <td>
        <strong>{lib.name}</strong>
      </td>
      <td>
        <code title={lib.hash} data-testid={`library-hash-${lib.name}`}>
          {shortHash(lib.hash)}
        </code>
      </td>
      <td>
        {lib.sourceFile} <span className="rs-tree-detail">({lib.origin === 'plcopen' ? 'PLCopen XML' : 'Rungsmith project'})</span>
      </td>
      <td>{dateText(lib.addedAt)}</td>
      <td>
        {libraryContents(lib)}
        <ul className="rs-library-blocks">
          {lib.pous.map((p) => (
            <li key={p.id}>
              <button
                type="button"
                className="rs-link-button"
                aria-pressed={viewing === p.id}
                data-testid={`library-view-${p.name}`}
                title={`View ${p.name} (read-only)`}
                onClick={() => libraryUi.getState().setViewing(viewing === p.id ? undefined : p.id)}
              >
                {p.name}
              </button>{' '}
              <span className="rs-tree-detail">{p.kind === 'FUNCTION' ? 'fn' : 'FB'}, {p.language}</span>
            </li>
          ))}
          {(lib.dataTypes ?? []).map((d) => (
            <li key={`type-${d.name}`}>
              <code>{d.name}</code> <span className="rs-tree-detail">data type</span>
            </li>
          ))}
        </ul>
      </td>
      <td data-testid={`library-uses-${lib.name}`}>{uses}</td>
      <td className="rs-library-actions">
        <button type="button" className="rs-button" data-testid={`library-update-${lib.name}`} title={`Update ${lib.name} from a newer file`} onClick={() => chooseLibraryFile(lib.name)}>
          Update…
        </button>
        <button type="button" className="rs-button" data-testid={`library-remove-${lib.name}`} title={`Remove ${lib.name} (refused while POUs use its blocks)`} onClick={onRemove}>
          Remove
        </button>
      </td>
    </tr>
  );
}

/** A file read for an add or an update: what it holds, what changes, and the confirmation. */
function PendingPanel({ pending }: { readonly pending: PendingLibrary }) {
  const store = useDocumentStore();
  const project = useDocument(selectProject);
  const { read } = pending;
  const [name, setName] = useState(read.ok ? read.library.name : '');
  const [errors, setErrors] = useState<readonly string[]>([]);
  useEffect(() => {
    setName(read.ok ? read.library.name : '');
    setErrors([]);
  }, [read]);
  const cancel = () => libraryUi.getState().setPending(undefined);
  const old = pending.updating ? project.libraries?.find((l) => l.name === pending.updating) : undefined;
  const diff = useMemo(() => (read.ok && old ? diffLibrary(old, read.library) : undefined), [read, old]);
  const affected = useMemo(
    () => (diff && old ? usesOf(project, [...diff.removed, ...diff.changed.map((c) => c.name), ...diff.typesRemoved, ...diff.typesChanged], old.name) : []),
    [diff, old, project],
  );
  if (!read.ok)
    return (
      <div role="alert" className="rs-library-pending" data-testid="library-pending">
        <p className="rs-error-text">{pending.fileName} cannot be used as a library:</p>
        <ul className="rs-load-errors" data-testid="library-errors">
          {read.errors.map((e, i) => (
            <li key={i}>{e}</li>
          ))}
        </ul>
        <button type="button" className="rs-button" onClick={cancel}>
          OK
        </button>
      </div>
    );
  const lib = read.library;
  const shadows = libraryShadows(project, lib);
  return (
    <div className="rs-library-pending" data-testid="library-pending" role="group" aria-label={old ? `Update ${old.name}` : 'Add a library'}>
      <h3>{old ? `Update ${old.name} from ${pending.fileName}` : `Add ${pending.fileName} as a library`}</h3>
      {old ? (
        <p>
          Version <code>{shortHash(old.hash)}</code> ({old.sourceFile}) becomes <code>{shortHash(lib.hash)}</code>.
          {old.hash === lib.hash ? ' The file is the one the library was read from: nothing changes.' : ''}
        </p>
      ) : (
        <label className="rs-library-name">
          Library name{' '}
          <input value={name} data-testid="library-name" onChange={(e) => setName(e.target.value)} />
        </label>
      )}
      <p data-testid="library-contents">
        {libraryContents(lib)}: {[...lib.pous.map((p) => p.name), ...(lib.dataTypes ?? []).map((d) => d.name)].join(', ')}. Version{' '}
        <code>{shortHash(lib.hash)}</code>.
      </p>
      {diff && (
        <ul className="rs-library-diff" data-testid="library-diff">
          {diff.added.map((n) => (
            <li key={`a-${n}`}>added: {n}</li>
          ))}
          {diff.removed.map((n) => (
            <li key={`r-${n}`} className="rs-error-text">
              removed: {n}
            </li>
          ))}
          {diff.changed.map((c) => (
            <li key={`c-${c.name}`}>
              interface changed: <code>{c.was}</code> → <code>{c.now}</code>
            </li>
          ))}
          {diff.bodyChanged.map((n) => (
            <li key={`b-${n}`}>body changed: {n}</li>
          ))}
          {diff.typesAdded.map((n) => (
            <li key={`ta-${n}`}>data type added: {n}</li>
          ))}
          {diff.typesRemoved.map((n) => (
            <li key={`tr-${n}`} className="rs-error-text">
              data type removed: {n}
            </li>
          ))}
          {diff.typesChanged.map((n) => (
            <li key={`tc-${n}`}>data type changed: {n}</li>
          ))}
          {!diff.added.length && !diff.removed.length && !diff.changed.length && !diff.bodyChanged.length && !diff.typesAdded.length && !diff.typesRemoved.length && !diff.typesChanged.length && (
            <li>no block or data type changes</li>
          )}
        </ul>
      )}
      {affected.length > 0 && (
        <div data-testid="library-affected">
          <p className="rs-error-text">
            {affected.length} use{affected.length === 1 ? '' : 's'} of removed or changed blocks need attention after the update (a call of a removed block
            becomes an LD-E01 error at its box; check the wiring of a changed interface):
          </p>
          <ul>
            {affected.map((u, i) => (
              <li key={i}>{describeUse(u)}</li>
            ))}
          </ul>
        </div>
      )}
      {read.notes.length > 0 && (
        <ul className="rs-library-notes" data-testid="library-notes">
          {read.notes.map((n, i) => (
            <li key={i}>{n}</li>
          ))}
        </ul>
      )}
      {shadows.length > 0 && (
        <ul className="rs-library-notes">
          {shadows.map((n, i) => (
            <li key={i}>{n}</li>
          ))}
        </ul>
      )}
      {errors.length > 0 && (
        <div role="alert" data-testid="library-errors">
          <p className="rs-error-text">{old ? 'The update is refused:' : 'The library cannot be added:'}</p>
          <ul className="rs-load-errors">
            {errors.map((e, i) => (
              <li key={i}>{e}</li>
            ))}
          </ul>
        </div>
      )}
      <div className="rs-library-confirm">
        <button type="button" className="rs-button" data-testid="library-cancel" onClick={cancel}>
          Cancel
        </button>
        <button
          type="button"
          className="rs-button rs-primary"
          data-testid="library-confirm"
          onClick={() => setErrors(old ? commitUpdate(store, old.name, lib) : commitAdd(store, lib, name))}
        >
          {old ? 'Update' : 'Add'}
        </button>
      </div>
    </div>
  );
}

/** A library block, read-only: its interface, and its body (LD drawn as in print, text as written). */
function BlockView({ library, pou }: { readonly library: ProjectLibrary; readonly pou: Pou }) {
  const project = useDocument(selectProject);
  const drawings = useMemo(() => {
    if (pou.language !== 'LD' || !pou.networks.length) return [];
    const theme = readCanvasTheme();
    const measure = canvasMeasure();
    const lib = blockLibrary(project);
    return pou.networks.map((n) => networkSvg(n, theme, measure, lib).svg);
  }, [pou, project]);
  return (
    <section className="rs-library-block" data-testid="library-block-view" aria-label={`${pou.name} (read-only)`}>
      <h3>
        {pou.name} <span className="rs-tree-detail">— {pou.kind === 'FUNCTION' ? 'function' : 'function block'} of the library {library.name}, read-only</span>
      </h3>
      {pou.comment && <p>{pou.comment}</p>}
      <p>
        <code data-testid="library-block-interface">{interfaceText(pou, library.dataTypes)}</code>
      </p>
      <table className="rs-library-vars">
        <thead>
          <tr>
            <th>Class</th>
            <th>Name</th>
            <th>Type</th>
            <th>Initial</th>
            <th>Comment</th>
          </tr>
        </thead>
        <tbody>
          {pou.variables.map((v) => (
            <tr key={v.name}>
              <td>{v.varClass}</td>
              <td>
                <code>{v.name}</code>
              </td>
              <td>
                <code>{v.type}</code>
              </td>
              <td>{v.initial ?? ''}</td>
              <td>{v.comment}</td>
            </tr>
          ))}
        </tbody>
      </table>
      {pou.language === 'LD' ? (
        drawings.length ? (
          drawings.map((svg, i) => (
            <div key={i} className="rs-library-network">
              <strong>Network {i + 1}</strong>
              <div role="img" aria-label={`Network ${i + 1} of ${pou.name}`} dangerouslySetInnerHTML={{ __html: svg }} />
            </div>
          ))
        ) : (
          <p className="rs-tree-detail">(no networks)</p>
        )
      ) : (
        <pre className="rs-library-source" data-testid="library-block-source">
          {pou.source || '(empty body)'}
        </pre>
      )}
    </section>
  );
}
