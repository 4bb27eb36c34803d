#version 110
// One colour for every covered pixel (the visibility output without shadows).
uniform vec4 u_color;

void main()
{
    gl_FragColor = u_color;
}
