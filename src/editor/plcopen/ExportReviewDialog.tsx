// The export review: before the PLCopen download, what Beremiz and OpenPLC would run differently
// (LD-X rules, src/plcopen/exportBehaviour.ts), grouped by POU and network. A network's name goes
// to it; "Apply fix" applies the equivalent that behaves the same (one undo step) and the list
// follows the project; "Export anyway" downloads the file as it is.
import { useMemo } from 'react';
import { useStore } from 'zustand';
import { exportBehaviour, type ExportWarning } from '../../plcopen/exportBehaviour';
import { useDocumentStore } from '../../store/documentStore';
import type { Project } from '../../model/project';
import { elementPlace } from '../problems/describe';
import { useUiStore } from '../../store/uiStore';
import { ModalDialog } from '../files/ModalDialog';
import { CancelOr } from './CancelOrButtons';
import { revealNetwork } from '../outline/goTo';
import { applyExportFixTo, downloadPlcopenFile } from './plcopenActions';
import { plcopenUi } from './plcopenUi';

interface NetworkGroup {
  readonly key: string;
  readonly title: string;
  readonly warnings: ExportWarning[];
}

/** Warnings by POU, then by network, in project order. */
function grouped(warnings: readonly ExportWarning[]): { pou: string; networks: NetworkGroup[] }[] {
  const pous = new Map<string, Map<string, NetworkGroup>>();
  for (const w of warnings) {
    let nets = pous.get(w.pou);
    if (!nets) pous.set(w.pou, (nets = new Map()));
    const key = w.networkId;
    let g = nets.get(key);
    if (!g) {
      const title = `Network ${w.network + 1}${w.networkLabel ? ` (${w.networkLabel})` : ''}`;
      nets.set(key, (g = { key, title, warnings: [] }));
    }
    g.warnings.push(w);
  }
  return [...pous].map(([pou, nets]) => ({ pou, networks: [...nets.values()] }));
}

/** The element a warning is about, by id in its network. */
function elementOf(project: Project, w: ExportWarning) {
  if (!w.elementId) return undefined;
  const pou = project.pous.find((p) => p.id === w.pouId);
  return pou?.networks.find((n) => n.id === w.networkId)?.elements.find((e) => e.id === w.elementId);
}

export function ExportReviewDialog() {
  const open = useStore(plcopenUi, (s) => s.reviewingExport);
  return open ? <ReviewBody /> : null;
}

function ReviewBody() {
  const doc = useDocumentStore();
  const ui = useUiStore();
  const project = useStore(doc, (s) => s.project);
  const warnings = useMemo(() => exportBehaviour(project), [project]);
  const close = () => plcopenUi.getState().setReviewingExport(false);
  const goTo = (w: ExportWarning) => {
    close();
    revealNetwork({ doc, ui }, w.pouId, w.networkId, w.cell);
  };
  const n = warnings.length;
  return (
    <ModalDialog
      role="dialog"
      titleId="rs-export-review-title"
      title="Export PLCopen XML"
      className="rs-plcopen-report"
      testId="export-review"
      onClose={close}
      buttons={
        <CancelOr
          label={n ? 'Export anyway' : 'Export'}
          onCancel={close}
          onConfirm={() => {
            close();
            downloadPlcopenFile(doc);
          }}
        />
      }
    >
      {n ? (
        <p>
          Beremiz and OpenPLC would run {n} thing{n === 1 ? '' : 's'} in this project differently from
          Rungsmith: their code generator drops jumps and RETURN, calls some blocks late and re-reads
          contacts per coil. The exported XML is the same either way.
        </p>
      ) : (
        <p data-testid="export-review-clear">
          Nothing behaves differently any more: the export runs the same in Beremiz and OpenPLC.
        </p>
      )}
      <div className="rs-plcopen-issues" data-testid="export-review-list">
        {grouped(warnings).map((p) => (
          <section key={p.pou}>
            <h3>{p.pou}</h3>
            {p.networks.map((g) => (
              <div key={g.key} className="rs-export-network">
                <button
                  type="button"
                  className="rs-export-goto"
                  title="Go to this network"
                  onClick={() => goTo(g.warnings[0]!)}
                >
                  {g.title}
                </button>
                <ul>
                  {g.warnings.map((w, k) => (
                    <li key={k} data-testid="export-warning">
                      <code>{w.rule}</code>
                      {w.cell ? <span className="rs-export-place" data-testid="export-warning-place"> {elementPlace(w.cell, elementOf(project, w))}:</span> : null} {w.message}
                      {w.fix ? (
                        <div>
                          <button
                            type="button"
                            className="rs-button"
                            title={w.fix.label}
                            onClick={() => applyExportFixTo(doc, w.fix!)}
                          >
                            Apply fix: {w.fix.label}
                          </button>
                        </div>
                      ) : null}
                    </li>
                  ))}
                </ul>
              </div>
            ))}
          </section>
        ))}
      </div>
    </ModalDialog>
  );
}
