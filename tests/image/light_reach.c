#include "light_reach.h"

#include <math.h>

int light_reaches(const scene *s, const ref_hit *h)
{
    const scene_light *l = &s->lights[0];
    const float *eye = s->camera.eye;
    double to_eye = 0, to_light = 0, len = 0, along = 0;
    int k;
    for (k = 0; k < 3; k++) {
        double L = l->type == SCENE_LIGHT_DIRECTIONAL ? -l->direction[k] : l->position[k] - h->P[k];
        to_eye += h->Ng[k] * (eye[k] - h->P[k]);
        to_light += h->Ng[k] * L;
        len += L * L;
        along += -L * l->direction[k];
    }
    if ((to_eye >= 0) != (to_light > 0))
        return 0;
    if (l->type == SCENE_LIGHT_SPOT &&
        along / sqrt(len) < cos(l->spot_cutoff_deg * 3.14159265358979323846 / 180.0))
        return 0;
    return 1;
}
