// TypeDoc plugin: names each documented module by the specifier a user imports it with, not by its file's path.
import { Converter, ReflectionKind } from 'typedoc';

const IMPORT_NAMES = { index: 'rtl-wasm', 'ros/logs': 'rtl-wasm/logs', 'ros/messages': 'rtl-wasm/ros' };

export function load(app) {
  app.converter.on(Converter.EVENT_CREATE_DECLARATION, (_context, reflection) => {
    if (reflection.kindOf(ReflectionKind.Module) && Object.hasOwn(IMPORT_NAMES, reflection.name)) {
      reflection.name = IMPORT_NAMES[reflection.name];
    }
  });
}
