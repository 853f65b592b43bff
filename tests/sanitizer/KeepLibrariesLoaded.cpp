// Linked into every executable of a sanitizer build only (DW_SANITIZE; see
// tests/sanitizer/lsan.supp). Mesa's EGL loads its driver (swrast_dri.so)
// with dlopen and unloads it at eglTerminate; LeakSanitizer reports the
// driver's allocations at exit, when the driver is no longer mapped, as
// "<unknown module>", which no suppression can name. This dlclose, which the
// executable's definition interposes for every library, keeps each library
// mapped, so the leak reports name Mesa's libraries and lsan.supp matches
// them by name, and nothing of the workbench is suppressed.
extern "C" int dlclose(void* /*handle*/) { return 0; }
