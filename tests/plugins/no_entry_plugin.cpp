// A shared library that is not a radarpr plugin: it exports a function, but no RADARPR_PLUGIN
// entry point. The loader must refuse it by name.
extern "C" __attribute__((visibility("default"))) int not_a_radarpr_plugin() {
  return 42;
}
