/* SPDX-License-Identifier: MIT */
/* Logging through the caller's callback, with a formatter that never allocates. */
#include "internal.h"

static size_t put_char(char *buf, size_t size, size_t at, char c)
{
    if (at + 1 < size)
        buf[at] = c;
    return at + 1;
}

static size_t put_str(char *buf, size_t size, size_t at, const char *s)
{
    if (!s)
        s = "(null)";
    while (*s)
        at = put_char(buf, size, at, *s++);
    return at;
}

static size_t put_unsigned(char *buf, size_t size, size_t at, unsigned long long v, unsigned base)
{
    char digits[24];
    int n = 0;
    do {
        unsigned d = (unsigned)(v % base);
        digits[n++] = (char)(d < 10 ? '0' + d : 'a' + d - 10);
        v /= base;
    } while (v && n < (int)sizeof digits);
    while (n > 0)
        at = put_char(buf, size, at, digits[--n]);
    return at;
}

static size_t put_signed(char *buf, size_t size, size_t at, long long v)
{
    if (v < 0) {
        at = put_char(buf, size, at, '-');
        return put_unsigned(buf, size, at, (unsigned long long)(-(v + 1)) + 1u, 10);
    }
    return put_unsigned(buf, size, at, (unsigned long long)v, 10);
}

/* Three decimals are enough for log lines; no locale, no heap. */
static size_t put_float(char *buf, size_t size, size_t at, double v)
{
    unsigned long long whole, frac;
    if (v != v)
        return put_str(buf, size, at, "nan");
    if (v < 0) {
        at = put_char(buf, size, at, '-');
        v = -v;
    }
    if (v > 1e18)
        return put_str(buf, size, at, "inf");
    whole = (unsigned long long)v;
    frac = (unsigned long long)((v - (double)whole) * 1000.0 + 0.5);
    if (frac >= 1000) {
        whole++;
        frac -= 1000;
    }
    at = put_unsigned(buf, size, at, whole, 10);
    at = put_char(buf, size, at, '.');
    at = put_char(buf, size, at, (char)('0' + frac / 100));
    at = put_char(buf, size, at, (char)('0' + frac / 10 % 10));
    return put_char(buf, size, at, (char)('0' + frac % 10));
}

size_t stin__format(char *buf, size_t size, const char *fmt, va_list ap)
{
    size_t at = 0;
    for (; *fmt; fmt++) {
        if (*fmt != '%') {
            at = put_char(buf, size, at, *fmt);
            continue;
        }
        fmt++;
        switch (*fmt) {
        case 's': at = put_str(buf, size, at, va_arg(ap, const char *)); break;
        case 'd': at = put_signed(buf, size, at, va_arg(ap, int)); break;
        case 'u': at = put_unsigned(buf, size, at, va_arg(ap, unsigned), 10); break;
        case 'x': at = put_unsigned(buf, size, at, va_arg(ap, unsigned), 16); break;
        case 'f': at = put_float(buf, size, at, va_arg(ap, double)); break;
        case 'l':
            if (fmt[1] == 'u') {
                fmt++;
                at = put_unsigned(buf, size, at, va_arg(ap, unsigned long), 10);
            }
            break;
        case 'z':
            if (fmt[1] == 'u') {
                fmt++;
                at = put_unsigned(buf, size, at, va_arg(ap, size_t), 10);
            }
            break;
        case '%': at = put_char(buf, size, at, '%'); break;
        case '\0': fmt--; break;
        default: break;
        }
    }
    if (size)
        buf[at < size ? at : size - 1] = '\0';
    return at;
}

size_t stin__formatf(char *buf, size_t size, const char *fmt, ...)
{
    va_list ap;
    size_t n;
    va_start(ap, fmt);
    n = stin__format(buf, size, fmt, ap);
    va_end(ap);
    return n;
}

void stin__logv(stin_log_fn fn, void *user, stin_log_level level, stin_log_item item,
                const char *fmt, va_list ap)
{
    char line[1024];
    if (!fn)
        return;
    stin__format(line, sizeof line, fmt, ap);
    fn(user, level, item, line);
}

void stin__log(struct stin_context *ctx, stin_log_level level, stin_log_item item,
               const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    stin__logv(ctx->desc.log, ctx->desc.log_user, level, item, fmt, ap);
    va_end(ap);
}
