// Shows the Plant tab (issue 26): a project or example that names a machine opens with the machine
// in view, not behind one of the side panel's tabs.
export function showPlantTab(): void {
  if (typeof document !== 'undefined') document.getElementById('rs-tab-plant')?.click();
}
