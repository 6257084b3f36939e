#version 450 core
// Depth alone (colour writes are off): the renderer draws the multisampled
// opaque meshes' depth again at the pixel centres of the one-sample scene
// with mesh.vert and this (see depthAtCentres).
void main() {}
