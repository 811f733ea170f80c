// Lecture mode: the figure fills the screen beside the explanation in large type, for a projector, and the keyboard
// drives everything: ← / → step, Space plays or pauses, Home / End jump, L toggles the mode, Escape leaves it.
// The mode is a class on <html> (rem sizes follow it) (the layout lives in style.css); the figure reads its text size from CSS.
const TYPING = new Set(['INPUT', 'SELECT', 'TEXTAREA']);

// player: the page's Player; button: the toggle button (aria-pressed mirrors the mode); onChange(on) after a toggle.
export function wireLecture({ player, button, onChange }) {
  const root = document.documentElement;
  const isOn = () => root.classList.contains('lecture');
  const set = (on) => {
    root.classList.toggle('lecture', on);
    button.setAttribute('aria-pressed', String(on));
    button.textContent = on ? 'Leave lecture mode (L)' : 'Lecture mode (L)';
    onChange?.(on);
  };
  button.addEventListener('click', () => set(!isOn()));
  // capture: in lecture mode the arrows step the player even when the figure (whose arrows pan) has the focus
  window.addEventListener('keydown', (ev) => {
    if (ev.ctrlKey || ev.metaKey || ev.altKey) return;
    const typing = TYPING.has(ev.target.tagName) && ev.target.type !== 'range';
    if (typing) return;
    if (ev.key === 'l' || ev.key === 'L') { ev.preventDefault(); set(!isOn()); return; }
    if (!isOn()) return;
    const act = {
      ArrowRight: () => player.go(player.step + 1), ArrowLeft: () => player.go(player.step - 1),
      ' ': () => player.toggle(), Home: () => player.go(0), End: () => player.go(player.steps - 1),
      Escape: () => set(false),
    }[ev.key];
    if (!act) return;
    ev.preventDefault();
    ev.stopPropagation();
    if (ev.key !== ' ' && ev.key !== 'Escape') player.pause();
    act();
  }, true);
  return { set, get on() { return isOn(); } };
}
