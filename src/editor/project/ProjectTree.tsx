// The project tree: programs, function blocks and functions (with kind icons), the data types,
// the global variables and the tasks. Click a POU to open it in a tab; add, rename, duplicate and delete
// POUs (renames follow into calls, instance types and tasks; deleting a used POU asks first).
import { useState } from 'react';
import { libraryInfo } from '../../model/codesysUtil';
import type { PouId } from '../../model/ids';
import type { Pou, PouKind } from '../../model/project';
import { selectActivePouId, selectProject, useDocument, useDocumentStore } from '../../store/documentStore';
import { pouNameProblem, pouUsages } from '../../store/pouEdits';
import { OWN_TASK_MS, type NewPouLanguage, type RunIn } from '../../store/pouCommands';
import { DataTypesSection } from '../dataTypes/DataTypesSection';
import { LibrariesSection } from '../library/LibrariesSection';
import { dataTypeTabs } from '../dataTypes/dataTypeTabs';
import { focusVariable } from '../variables/variableFocus';
import { DeletePouDialog } from './DeletePouDialog';
import { TasksDialog } from './TasksDialog';
import { NameField } from './NameField';
import { PouProperties } from './PouProperties';
import { KIND_ICONS, KIND_TITLES } from './pouWords';
import './project.css';

const SECTIONS: readonly { kind: PouKind; title: string }[] = [
  { kind: 'PROGRAM', title: 'Programs' },
  { kind: 'FUNCTION_BLOCK', title: 'Function blocks' },
  { kind: 'FUNCTION', title: 'Functions' },
];

export function ProjectTree() {
  const store = useDocumentStore();
  const project = useDocument(selectProject);
  const activeId = useDocument(selectActivePouId);
  const [renaming, setRenaming] = useState<PouId | undefined>(undefined);
  const [deleting, setDeleting] = useState<Pou | undefined>(undefined);
  const [message, setMessage] = useState('');
  const [tasksOpen, setTasksOpen] = useState(false);
  const [language, setLanguage] = useState<NewPouLanguage>('LD');
  // Where + Program's new program runs: 'own' (a task of its own), a task's index, or 'none'.
  const [runIn, setRunIn] = useState<string>('own');

  const add = (kind: PouKind) => {
    const run: RunIn | undefined =
      kind !== 'PROGRAM'
        ? undefined
        : runIn === 'own'
          ? { kind: 'own' }
          : runIn === 'none' || !project.tasks[Number(runIn)]
            ? { kind: 'none' }
            : { kind: 'task', task: Number(runIn) };
    const id = store.getState().addPou(kind, undefined, language, run);
    if (id) setRenaming(id);
  };
  const remove = (pou: Pou) => {
    if (project.pous.length <= 1) return setMessage('The project needs at least one POU.');
    setMessage('');
    // Unused: delete at once (Undo brings it back); used: say where first.
    if (pouUsages(project, pou.name).length === 0) store.getState().deletePou(pou.id);
    else setDeleting(pou);
  };
  const active = project.pous.find((p) => p.id === activeId);

  return (
    <section className="rs-project-tree" aria-label="Project" data-testid="project-tree">
      <div className="rs-tree-toolbar" role="group" aria-label="Add a POU">
        <select
          className="rs-tree-language"
          data-testid="add-pou-language"
          aria-label="Language of a new POU"
          title="The language the next POU added is written in: Ladder (LD) or Structured Text (ST)"
          value={language}
          onChange={(e) => setLanguage(e.target.value as NewPouLanguage)}
        >
          <option value="LD">LD</option>
          <option value="ST">ST</option>
        </select>
        <button type="button" className="rs-button" data-testid="add-program" onClick={() => add('PROGRAM')}>
          + Program
        </button>
        <label className="rs-tree-runin">
          <span>runs in</span>
          <select
            className="rs-cell-input"
            data-testid="new-program-runs-in"
            aria-label="A new program runs in"
            title="Where + Program's new program runs: a cyclic task of its own (T_<name>, renamed with the program), an existing task, or none"
            value={runIn === 'own' || runIn === 'none' || project.tasks[Number(runIn)] ? runIn : 'own'}
            onChange={(e) => setRunIn(e.target.value)}
          >
            <option value="own">its own task ({OWN_TASK_MS} ms)</option>
            {project.tasks.map((t, i) => (
              <option key={`${i}:${t.name}`} value={String(i)}>
                task {t.name}
              </option>
            ))}
            <option value="none">no task</option>
          </select>
        </label>
        <button
          type="button"
          className="rs-button"
          data-testid="add-fb"
          onClick={() => add('FUNCTION_BLOCK')}
        >
          + FB
        </button>
        <button
          type="button"
          className="rs-button"
          data-testid="add-function"
          onClick={() => add('FUNCTION')}
        >
          + Function
        </button>
      </div>
      {message && (
        <p role="alert" className="rs-error-text rs-tree-message">
          {message}
        </p>
      )}
      <ul className="rs-tree" aria-label="POUs and project data">
        {SECTIONS.map(({ kind, title }) => {
          const pous = project.pous.filter((p) => p.kind === kind);
          return (
            <li key={kind} className="rs-tree-section">
              <span className="rs-tree-heading">
                {title} <span className="rs-tree-count">{pous.length}</span>
              </span>
              <ul aria-label={title}>
                {pous.map((pou) => (
                  <PouRow
                    key={pou.id}
                    pou={pou}
                    active={pou.id === activeId}
                    renaming={renaming === pou.id}
                    onOpen={() => {
                      store.getState().setActivePou(pou.id);
                      dataTypeTabs(store).getState().showPou();
                    }}
                    onStartRename={() => setRenaming(pou.id)}
                    onEndRename={() => setRenaming(undefined)}
                    onDuplicate={() => store.getState().duplicatePou(pou.id)}
                    onDelete={() => remove(pou)}
                  />
                ))}
                {pous.length === 0 && <li className="rs-tree-none">none</li>}
              </ul>
            </li>
          );
        })}
        <DataTypesSection />
        <LibrariesSection />
        <li className="rs-tree-section">
          <button
            type="button"
            className="rs-tree-node"
            data-testid="tree-globals"
            title="Show the global variables (VAR_GLOBAL) in the variable table"
            onClick={() => focusVariable('', true)}
          >
            <span className="rs-kind-icon" aria-hidden="true">
              G
            </span>
            Global variables <span className="rs-tree-count">{project.globals.length}</span>
          </button>
        </li>
        <li className="rs-tree-section">
          <span className="rs-tree-heading">
            Tasks <span className="rs-tree-count">{project.tasks.length}</span>
            <button
              type="button"
              className="rs-icon-button"
              data-testid="tree-tasks-edit"
              title="Configure the tasks: interval, priority and the programs they run"
              onClick={() => setTasksOpen(true)}
            >
              ⚙
            </button>
          </span>
          <ul aria-label="Tasks">
            {project.tasks.map((t) => (
              <li key={t.name} className="rs-tree-task" data-testid={`tree-task-${t.name}`}>
                <span className="rs-mono">{t.name}</span>{' '}
                <span className="rs-tree-detail">
                  {t.single ? `when ${t.single} rises` : `every ${t.cycleMs} ms`}, priority {t.priority}
                </span>
                <ul>
                  {t.programs.map((p) => (
                    <li key={p.instance} className="rs-tree-detail">
                      <span className="rs-mono">{p.instance}</span> : {p.pou}
                    </li>
                  ))}
                </ul>
              </li>
            ))}
          </ul>
        </li>
      </ul>
      {active && <PouProperties key={active.id} pou={active} />}
      {tasksOpen && <TasksDialog onClose={() => setTasksOpen(false)} />}
      {deleting && (
        <DeletePouDialog
          pou={deleting}
          uses={pouUsages(project, deleting.name)}
          onCancel={() => setDeleting(undefined)}
          onDelete={() => {
            store.getState().deletePou(deleting.id);
            setDeleting(undefined);
          }}
        />
      )}
    </section>
  );
}

interface PouRowProps {
  readonly pou: Pou;
  readonly active: boolean;
  readonly renaming: boolean;
  readonly onOpen: () => void;
  readonly onStartRename: () => void;
  readonly onEndRename: () => void;
  readonly onDuplicate: () => void;
  readonly onDelete: () => void;
}

function PouRow({
  pou,
  active,
  renaming,
  onOpen,
  onStartRename,
  onEndRename,
  onDuplicate,
  onDelete,
}: PouRowProps) {
  return (
    <li className={active ? 'rs-tree-pou rs-active' : 'rs-tree-pou'} data-testid={`tree-pou-${pou.name}`}>
      {renaming ? (
        <RenameField pou={pou} onDone={onEndRename} />
      ) : (
        <button
          type="button"
          className="rs-tree-node"
          aria-current={active ? 'page' : undefined}
          title={`${KIND_TITLES[pou.kind]} ${pou.name}${pou.language === 'LD' ? '' : ` (${pou.language}${pou.language === 'ST' && !libraryInfo(pou) ? '' : ', read-only'})`}: click to open, double-click to rename`}
          onClick={onOpen}
          onDoubleClick={onStartRename}
          onKeyDown={(e) => {
            if (e.key === 'F2') {
              e.preventDefault();
              onStartRename();
            }
          }}
        >
          <span className={`rs-kind-icon rs-kind-${pou.kind}`} aria-hidden="true">
            {KIND_ICONS[pou.kind]}
          </span>
          <span className="rs-mono rs-tree-name">{pou.name}</span>
          {pou.language !== 'LD' && <span className="rs-tree-lang">{pou.language}</span>}
        </button>
      )}
      <span className="rs-tree-actions">
        <button
          type="button"
          className="rs-icon-button"
          aria-label={`Rename ${pou.name}`}
          title={`Rename ${pou.name} (F2); calls, instances and tasks follow`}
          onClick={onStartRename}
        >
          ✎
        </button>
        <button
          type="button"
          className="rs-icon-button"
          aria-label={`Duplicate ${pou.name}`}
          title={`Duplicate ${pou.name}`}
          onClick={onDuplicate}
        >
          ❐
        </button>
        <button
          type="button"
          className="rs-icon-button"
          aria-label={`Delete ${pou.name}`}
          title={`Delete ${pou.name}`}
          onClick={onDelete}
        >
          ×
        </button>
      </span>
    </li>
  );
}

/** The POU's name being edited: Enter renames (when the name is free), Escape keeps the old one. */
function RenameField({ pou, onDone }: { readonly pou: Pou; readonly onDone: () => void }) {
  const store = useDocumentStore();
  const project = useDocument(selectProject);
  return (
    <NameField
      name={pou.name}
      testId="pou-rename"
      problem={(text) => pouNameProblem(project, text, pou.id)}
      onRename={(text) => store.getState().renamePou(pou.id, text)}
      onDone={onDone}
    />
  );
}
