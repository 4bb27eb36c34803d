#version 150
// One colour for every covered pixel (the visibility output without shadows).
out vec4 frag_color;
uniform vec4 u_color;

void main()
{
    frag_color = u_color;
}
