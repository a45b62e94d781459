export function App() {
  return (
    <main>
      <h1>Rungsmith</h1>
    </main>
  );
}
