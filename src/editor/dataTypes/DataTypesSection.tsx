// The "Data types" group of the project tree: each data type with its kind; click opens it in a
// tab, double-click or F2 renames it (declarations follow), duplicate, delete (when used, a dialog
// says where first). "+ Data type" adds one of the chosen kind and starts renaming it.
import { useState } from 'react';
import type { DataType } from '../../model/project';
import {
  DATA_TYPE_KIND_WORDS,
  dataTypeNameProblem,
  dataTypeUsages,
  describeDataTypeUse,
  type DataTypeKind,
} from '../../store/dataTypeCommands';
import { selectProject, useDocument, useDocumentStore } from '../../store/documentStore';
import { ModalDialog } from '../files/ModalDialog';
import { NameField } from '../project/NameField';
import { dataTypeTabs, useDataTypeTabs } from './dataTypeTabs';

const KINDS = Object.keys(DATA_TYPE_KIND_WORDS) as DataTypeKind[];

export function DataTypesSection() {
  const store = useDocumentStore();
  const project = useDocument(selectProject);
  const shown = useDataTypeTabs((s) => s.shown);
  const types = project.dataTypes ?? [];
  const [kind, setKind] = useState<DataTypeKind>('struct');
  const [renaming, setRenaming] = useState<string | undefined>(undefined);
  const [deleting, setDeleting] = useState<DataType | undefined>(undefined);
  const tabs = () => dataTypeTabs(store).getState();

  const add = () => {
    const name = store.getState().addDataType(kind);
    if (!name) return;
    tabs().openType(name);
    setRenaming(name);
  };
  const remove = (t: DataType) => {
    if (dataTypeUsages(project, t.name).length > 0) return setDeleting(t);
    store.getState().deleteDataType(t.name);
    tabs().closeType(t.name);
  };
  return (
    <li className="rs-tree-section" data-testid="tree-datatypes">
      <span className="rs-tree-heading">
        Data types <span className="rs-tree-count">{types.length}</span>
      </span>
      <div className="rs-tree-toolbar" role="group" aria-label="Add a data type">
        <select aria-label="Kind of data type" className="rs-cell-input" value={kind}
          onChange={(e) => setKind(e.target.value as DataTypeKind)} data-testid="datatype-kind">
          {KINDS.map((k) => <option key={k} value={k}>{DATA_TYPE_KIND_WORDS[k]}</option>)}
        </select>
        <button type="button" className="rs-button" data-testid="add-datatype" onClick={add}>+ Data type</button>
      </div>
      <ul aria-label="Data types">
        {types.map((t) => {
          const active = shown !== undefined && shown.toUpperCase() === t.name.toUpperCase();
          return (
            <li key={t.name} className={active ? 'rs-tree-pou rs-active' : 'rs-tree-pou'} data-testid={`tree-datatype-${t.name}`}>
              {renaming === t.name ? (
                <NameField name={t.name} testId="datatype-rename" problem={(text) => dataTypeNameProblem(project, text, t.name)}
                  onRename={(text) => store.getState().renameDataType(t.name, text) && tabs().renamed(t.name, text.trim())}
                  onDone={() => setRenaming(undefined)} />
              ) : (
                <button type="button" className="rs-tree-node" aria-current={active ? 'page' : undefined}
                  title={`${DATA_TYPE_KIND_WORDS[t.def.kind]} ${t.name}: click to open, double-click to rename`}
                  onClick={() => tabs().openType(t.name)} onDoubleClick={() => setRenaming(t.name)}
                  onKeyDown={(e) => {
                    if (e.key === 'F2') {
                      e.preventDefault();
                      setRenaming(t.name);
                    }
                  }}>
                  <span className="rs-kind-icon rs-kind-TYPE" aria-hidden="true">T</span>
                  <span className="rs-mono rs-tree-name">{t.name}</span>
                  <span className="rs-tree-lang">{t.def.kind}</span>
                </button>
              )}
              <span className="rs-tree-actions">
                <button type="button" className="rs-icon-button" aria-label={`Rename ${t.name}`}
                  title={`Rename ${t.name} (F2); declarations using it follow`} onClick={() => setRenaming(t.name)}>✎</button>
                <button type="button" className="rs-icon-button" aria-label={`Duplicate ${t.name}`} title={`Duplicate ${t.name}`}
                  onClick={() => {
                    const copy = store.getState().duplicateDataType(t.name);
                    if (copy) tabs().openType(copy);
                  }}>❐</button>
                <button type="button" className="rs-icon-button" aria-label={`Delete ${t.name}`} title={`Delete ${t.name}`}
                  onClick={() => remove(t)}>×</button>
              </span>
            </li>
          );
        })}
        {types.length === 0 && <li className="rs-tree-none">none</li>}
      </ul>
      {deleting && (
        <DeleteDataTypeDialog type={deleting} onCancel={() => setDeleting(undefined)}
          onDelete={() => {
            store.getState().deleteDataType(deleting.name);
            tabs().closeType(deleting.name);
            setDeleting(undefined);
          }} />
      )}
    </li>
  );
}

/** "Point is used: delete it anyway?" with every declaration and data type naming it. */
function DeleteDataTypeDialog(p: { readonly type: DataType; readonly onCancel: () => void; readonly onDelete: () => void }) {
  const project = useDocument(selectProject);
  const uses = dataTypeUsages(project, p.type.name);
  const name = p.type.name;
  return (
    <ModalDialog role="alertdialog" titleId="rs-delete-datatype-title" title={`Delete data type ${name}?`}
      describedBy="rs-delete-datatype-text" testId="delete-datatype-dialog" onClose={p.onCancel}
      buttons={
        <>
          <button type="button" className="rs-button" autoFocus onClick={p.onCancel}>Cancel</button>
          <button type="button" className="rs-button rs-primary" data-testid="confirm-delete-datatype" onClick={p.onDelete}>
            Delete {name}
          </button>
        </>
      }>
      <p id="rs-delete-datatype-text">
        {name} is used in {uses.length} place{uses.length === 1 ? '' : 's'}. The declarations stay and will name an
        unknown type; Undo brings {name} back.
      </p>
      <ul className="rs-delete-uses" data-testid="datatype-uses">
        {uses.map((u, i) => <li key={i}>{describeDataTypeUse(u)}</li>)}
      </ul>
    </ModalDialog>
  );
}
