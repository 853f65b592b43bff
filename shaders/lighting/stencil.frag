#version 450 core
// Stencil marking pass of the light-volume test: no colour, only stencil ops.
void main() {}
