// Minimal ScriptUI stand-in: enough of Window/controls for a modal dialog. show() hands the window to
// a responder (the test), which fills the named controls and picks a button, like a user would.

class Control {
  constructor(type, text, props) {
    this.type = type;
    this.text = text === undefined ? '' : text;
    this.properties = props || {};
    this.children = [];
    this.enabled = true;
    this.visible = true;
    this.value = false;
    this.items = [];
    this.selection = null;
    if (type === 'dropdownlist' || type === 'listbox') {
      const list = Array.isArray(text) ? text : [];
      this.text = '';
      this.items = list.map((t, index) => ({ text: String(t), index }));
    }
  }
  add(type, bounds, text, props) {
    const c = new Control(type, text, props);
    c.parent = this;
    this.children.push(c);
    return c;
  }
  /** ScriptUI allows `dropdown.selection = index`; reading gives the ListItem. */
  select(i) { this.selection = i === null ? null : this.items[i]; }
  findElement(name) {
    if (this.properties.name === name) return this;
    for (const c of this.children) { const f = c.findElement(name); if (f) return f; }
    return null;
  }
  all() { return [this, ...this.children.flatMap((c) => c.all())]; }
}

/**
 * Build the `Window` constructor for a script context. `respond(win)` must return 1 (OK) or 2 (Cancel);
 * it may set `.text` / `.value` / selection on controls found with `win.findElement(name)`.
 */
export function makeWindowClass(respond, log) {
  return class Window extends Control {
    constructor(type, title) {
      super(type, title);
      this.title = title;
    }
    show() {
      // ScriptUI semantics for dropdown `selection = n`: normalise numbers to ListItems.
      for (const c of this.all()) if (typeof c.selection === 'number') c.selection = c.items[c.selection];
      log.push(this);
      const button = respond ? respond(this) : 2;
      for (const c of this.all()) if (typeof c.selection === 'number') c.selection = c.items[c.selection];
      const pressed = this.all().find((c) => c.type === 'button' && c.properties.name === (button === 1 ? 'ok' : 'cancel'));
      if (pressed && pressed.onClick) pressed.onClick();
      return button;
    }
    close(v) { this.closedWith = v; }
    center() {}
  };
}
