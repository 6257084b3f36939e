#version 450 core
layout(location = 0) in vec3 aPosition;
uniform mat4 clipFromWorld;
void main() { gl_Position = clipFromWorld * vec4(aPosition, 1.0); }
