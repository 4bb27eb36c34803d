#version 150
// SPDX-License-Identifier: MIT
// No fragment work: OpenGL ES links no program without a fragment stage, so
// a transform-feedback-only program (vdsm's culling pass) takes this there.
void main()
{
}
