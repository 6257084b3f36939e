#version 450 core
// Depth alone (colour writes are off): the renderer draws the moving meshes
// that it draws in samples (arrows) at the pixel centres of the one-sample
// scene with mesh.vert and this, for their depth; their colour there comes
// from the resolve of their samples (see drawOpaqueAtCentres).
void main() {}
