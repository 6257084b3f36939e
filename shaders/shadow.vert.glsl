#version 450 core
// Depth-only pass from the key light.
layout(location = 0) in vec3 aPosition;
uniform mat4 lightClipFromModel;
void main() { gl_Position = lightClipFromModel * vec4(aPosition, 1.0); }
