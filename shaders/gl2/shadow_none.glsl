// No shadow test in the shader (none, or the stencil already decided).
float shadow_visibility(int i)
{
    return 1.0;
}
