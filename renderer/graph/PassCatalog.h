#pragma once
// Which passes a pipeline has: the built-in ones (renderer/passes/BuiltinPasses.cpp,
// one line each) and any registered from outside the library (a test binary,
// a plug-in) with one line:
//     static dw::RegisterPass<InvertPass> registerInvert(dw::PassStage::Post);
// Pipelines built after that line ran include the pass; nothing else changes.
#include <functional>
#include <memory>
#include <vector>

#include "renderer/graph/RenderPass.h"

namespace dw {

class KnobRegistry;

struct PassEntry {
    PassStage stage = PassStage::Screen;
    std::function<std::unique_ptr<RenderPass>(KnobRegistry&)> make;
};

class PassCatalog {
public:
    // Passes registered from outside the library.
    static PassCatalog& extra();
    void add(PassEntry entry) { entries_.push_back(std::move(entry)); }
    const std::vector<PassEntry>& entries() const { return entries_; }

private:
    std::vector<PassEntry> entries_;
};

// The built-in passes (renderer/passes/BuiltinPasses.cpp).
std::vector<PassEntry> builtinPasses();

template <typename T>
struct RegisterPass {
    explicit RegisterPass(PassStage stage) {
        PassCatalog::extra().add({stage, [](KnobRegistry& knobs) { return std::make_unique<T>(knobs); }});
    }
};

}  // namespace dw
