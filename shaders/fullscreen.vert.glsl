#version 330 core
// fullscreen.vert.glsl - one triangle that covers the viewport, from gl_VertexID alone (draw 3
// vertices with an empty vertex array): (-1,-1), (3,-1), (-1,3). It lies on the far plane
// (depth 1), so the sky, drawn after the opaque geometry with GL_LEQUAL, shades only the pixels
// nothing else covered.

out vec2 v_ndc; // normalised device coordinates of the pixel

void main() {
    vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
    v_ndc = p;
    gl_Position = vec4(p, 1.0, 1.0);
}
