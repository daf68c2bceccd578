// The wireframe overlay's lines: one colour in linear radiance, divided by the exposure so the
// lines look the same at any exposure once tone mapped. Alpha 1: a line covers its pixel.
uniform vec3 uWireColor;

out vec4 fragColor;

void main()
{
    fragColor = vec4(uWireColor, 1.0);
}
