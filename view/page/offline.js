// One-file replays. An exported champion (robozoo-view export, or the page's
// "Save this champion as HTML") carries the server's frames inline in
// <script type="application/json" id="robozoo-data">: offlineFrames() returns
// them (null on a served page), and the page feeds them through the same
// handler as the WebSocket's. setupSave() makes the save button ask the server
// for that file (GET /export?genome=N) and save it.
export function offlineFrames() {
  const el = document.getElementById("robozoo-data");
  return el ? JSON.parse(el.textContent) : null;
}

export function setupSave(button, currentId, offline) {
  if (!button) return;
  if (offline) { button.hidden = true; return; }
  button.addEventListener("click", async () => {
    const id = currentId();
    const label = button.textContent;
    button.disabled = true;
    button.textContent = "saving…";
    try {
      const r = await fetch(id === null ? "/export" : `/export?genome=${id}`);
      if (!r.ok) throw new Error((await r.text()).trim());
      const name = (r.headers.get("Content-Disposition") || "").match(/filename="([^"]+)"/);
      const a = document.createElement("a");
      a.href = URL.createObjectURL(await r.blob());
      a.download = name ? name[1] : "champion.html";
      document.body.appendChild(a);
      a.click();
      a.remove();
      setTimeout(() => URL.revokeObjectURL(a.href), 10000);
      button.textContent = label;
    } catch (err) {
      button.textContent = label;
      button.title = String(err.message || err);
      alert("Could not save: " + button.title);
    } finally {
      button.disabled = false;
    }
  });
}
