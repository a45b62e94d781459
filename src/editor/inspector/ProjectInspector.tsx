// Nothing selected: the project itself (name, description, semantics profile, online change mode).
import type { OnlineChangeMode, Profile } from '../../model/project';
import { selectProject, useDocument, useDocumentStore } from '../../store/documentStore';
import { CommitInput, CommitTextArea } from '../variables/CommitInput';

export function ProjectInspector() {
  const store = useDocumentStore();
  const project = useDocument(selectProject);
  const networks = project.pous.reduce((n, p) => n + p.networks.length, 0);
  return (
    <div data-testid="project-inspector">
      <h2>Project</h2>
      <p className="rs-inspector-where">
        {project.pous.length} POU{project.pous.length === 1 ? '' : 's'}, {networks} network
        {networks === 1 ? '' : 's'}. Select an element or a network to edit it.
      </p>
      <div className="rs-field">
        <label htmlFor="project-name">Name</label>
        <CommitInput
          id="project-name"
          className="rs-cell-input"
          value={project.name}
          onCommit={(name) => store.getState().updateProject({ name })}
        />
        <label htmlFor="project-profile">Semantics</label>
        <select
          id="project-profile"
          className="rs-cell-input"
          value={project.profile}
          onChange={(e) => store.getState().setProjectProfile(e.target.value as Profile)}
        >
          <option value="iec">IEC 61131-3 (standard)</option>
          <option value="openplc">OpenPLC / MATIEC</option>
        </select>
        <label htmlFor="project-online-change" title="How edits made while the simulation runs reach the running program">
          Online change
        </label>
        <select
          id="project-online-change"
          className="rs-cell-input"
          value={project.onlineChange ?? 'edit'}
          title="Apply as you edit: each edit goes in at the next scan boundary. Apply on request: edits wait for Apply (Alt+F8), which lists them first."
          onChange={(e) => store.getState().updateProject({ onlineChange: e.target.value as OnlineChangeMode })}
          data-testid="sim-online-mode"
        >
          <option value="edit">Apply as you edit</option>
          <option value="request">Apply on request</option>
        </select>
      </div>
      <div className="rs-field">
        <label htmlFor="project-description">Description</label>
        <CommitTextArea
          id="project-description"
          value={project.description}
          onCommit={(description) => store.getState().updateProject({ description })}
        />
      </div>
    </div>
  );
}
