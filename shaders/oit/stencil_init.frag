#version 450 core
// The A-buffer's stencil initialisation (seed 000 section 5.9): drawn once
// per sample with glSampleMaski selecting that sample and the stencil
// reference 2 + sample index replaced; it writes no colour.
void main() {}
