<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/common/units.xsl - values written with a unit ("8GB", "512 MiB",
  "1 Gbit/s", "100 Mbps", "3 ms", "100 Hz"): the one parser of every
  numeric value that has a dimension (docs/profile.md, "Values with
  units"). bind reads every such tag and convention attribute through it
  (xslt/m2m/bind/values.xsl, fp:quantity).

  Reads:   nothing.  Writes: numbers and strings.  Params: none.
  Errors:  none raised here: f:quantity returns () for a value it cannot
           read, and the caller refuses it with f:quantity-forms, the
           accepted form, in its message.
    f:quantity($text, $dimension)  the value in the dimension's canonical
                          unit, as xs:double, or () when $text is no
                          non-negative number with an accepted unit
    f:quantity-forms($dimension)  the accepted forms, for messages
    f:quantity-units($dimension)  the accepted unit spellings
    f:quantity-noun($dimension)   what a value of the dimension is called

  Dimensions and their canonical units (what a bare number means, as
  before units were read):
    time       seconds: s, ms, us / µs / μs (micro), ns, min
    period     a time, or a frequency whose period it is: Hz, kHz
               (100 Hz = 0.01 s; 0 Hz has no period and is refused)
    memory     MiB: B, kB (10^3 B), MB (10^6), GB (10^9), TB (10^12),
               KiB (2^10 B), MiB (2^20), GiB (2^30), TiB (2^40); K and k
               are both 1000 (write KiB for 1024); a bare G or M (which
               some tools mean as GiB) is refused as ambiguous
    bandwidth  Mbit/s: bit/s, kbit/s, Mbit/s, Gbit/s, Tbit/s (powers of
               1000), also written bps, kbps, Mbps, Gbps, Tbps or b/s, kb/s,
               Mb/s, Gb/s, Tb/s, and bytes
               per second B/s, kB/s, MB/s, GB/s (8 bits a byte, powers of
               1000) and KiB/s, MiB/s, GiB/s (powers of 1024)
  A unit follows the number, with or without spaces; units are case
  sensitive (b is a bit, B a byte; m milli, M mega), but for the prefix
  K / k. The number is a non-negative decimal, optionally with an
  exponent (1e3). Conversion: number x numerator div denominator in
  doubles (3 ms = 3 div 1000), so a value written in the canonical unit or
  a decimal fraction of it gives the double its decimal literal would.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <!-- unit spelling -> (numerator, denominator): canonical = number x
       numerator div denominator; a frequency unit's value is inverted -->
  <xsl:variable name="fp:time-units" as="map(xs:string, xs:decimal+)" select="map {
      's': (1, 1), 'sec': (1, 1), 'ms': (1, 1000), 'us': (1, 1000000), '&#xB5;s': (1, 1000000),
      '&#x3BC;s': (1, 1000000), 'ns': (1, 1000000000), 'min': (60, 1) }"/>
  <xsl:variable name="fp:frequency-units" as="map(xs:string, xs:decimal+)" select="map {
      'Hz': (1, 1), 'kHz': (1000, 1), 'KHz': (1000, 1) }"/>
  <xsl:variable name="fp:memory-units" as="map(xs:string, xs:decimal+)" select="map {
      'B': (1, 1048576), 'kB': (1000, 1048576), 'KB': (1000, 1048576), 'MB': (1000000, 1048576),
      'GB': (1000000000, 1048576), 'TB': (1000000000000, 1048576),
      'KiB': (1, 1024), 'MiB': (1, 1), 'GiB': (1024, 1), 'TiB': (1048576, 1) }"/>
  <xsl:variable name="fp:bandwidth-units" as="map(xs:string, xs:decimal+)" select="map:merge((
      for $p in ('', 'k', 'K', 'M', 'G', 'T') return
      let $bits := map { '': (1, 1000000), 'k': (1, 1000), 'K': (1, 1000), 'M': (1, 1), 'G': (1000, 1), 'T': (1000000, 1) }($p)
      return (map:entry($p || 'bit/s', $bits), map:entry($p || 'bps', $bits),
              map:entry($p || 'b/s', $bits), map:entry($p || 'B/s', ($bits[1] * 8, $bits[2]))),
      map { 'KiB/s': (8192, 1000000), 'MiB/s': (8388608, 1000000), 'GiB/s': (8589934592, 1000000) }))"/>

  <xsl:function name="f:quantity-units" as="map(xs:string, xs:decimal+)">
    <xsl:param name="dimension" as="xs:string"/>
    <xsl:sequence select="if ($dimension eq 'memory') then $fp:memory-units
        else if ($dimension eq 'bandwidth') then $fp:bandwidth-units
        else if ($dimension eq 'period') then map:merge(($fp:time-units, $fp:frequency-units))
        else $fp:time-units"/>
  </xsl:function>

  <xsl:function name="f:quantity" as="xs:double?">
    <xsl:param name="text" as="xs:string"/>
    <xsl:param name="dimension" as="xs:string"/>
    <xsl:variable name="value" as="xs:string" select="normalize-space($text)"/>
    <xsl:variable name="pattern" as="xs:string" select="'^(([0-9]+(\.[0-9]*)?|\.[0-9]+)([eE][+\-]?[0-9]+)?)(.*)$'"/>
    <xsl:variable name="number" as="xs:double?" select="$value[matches(., $pattern)] ! xs:double(replace(., $pattern, '$1'))"/>
    <xsl:variable name="unit" as="xs:string" select="normalize-space(replace($value, $pattern, '$5'))"/>
    <!-- no unit (a Java-style 0.01f / 0.01d too): the canonical unit -->
    <xsl:variable name="factor" as="xs:decimal*"
        select="if ($unit = ('', 'f', 'F', 'd', 'D')) then (1, 1) else f:quantity-units($dimension)($unit)"/>
    <xsl:sequence select="
        if (empty($number) or empty($factor)) then ()
        else if (map:contains($fp:frequency-units, $unit))
        then ($number * $factor[1] div $factor[2])[. gt 0] ! (1 div .)
        else $number * $factor[1] div $factor[2]"/>
  </xsl:function>

  <xsl:function name="f:quantity-noun" as="xs:string">
    <xsl:param name="dimension" as="xs:string"/>
    <xsl:sequence select="if ($dimension eq 'memory') then 'memory size' else $dimension"/>
  </xsl:function>

  <xsl:function name="f:quantity-forms" as="xs:string">
    <xsl:param name="dimension" as="xs:string"/>
    <xsl:sequence select="
        if ($dimension eq 'memory')
        then 'a non-negative number of MiB (8192), or one with a unit: B, kB, MB, GB, TB (powers of 1000: 8GB = 8,000,000,000 bytes), KiB, MiB, GiB, TiB (powers of 1024: 8 GiB = 8192 MiB)'
        else if ($dimension eq 'bandwidth')
        then 'a non-negative number of Mbit/s (1000), or one with a unit: bit/s, kbit/s, Mbit/s, Gbit/s (also bps, kbps, Mbps, Gbps, b/s, kb/s, Mb/s, Gb/s), B/s, kB/s, MB/s, GB/s (bytes, powers of 1000), KiB/s, MiB/s, GiB/s (powers of 1024)'
        else if ($dimension eq 'period')
        then 'a non-negative number of seconds (0.003), or one with a unit: s, ms, us, ns, min, or a frequency above 0 in Hz or kHz (100 Hz = 0.01 s)'
        else 'a non-negative number of seconds (0.003), or one with a unit: s, ms, us, ns, min'"/>
  </xsl:function>
</xsl:stylesheet>
