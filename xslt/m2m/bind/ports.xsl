<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/bind/ports.xsl - bind (xslt/m2m/bind.xsl): bound components and their data ports (seed 000 R2).

  Reads:   the PIM (urn:robomda:pim:1) and the working trees of fp:binding.
  Writes:  parts of pim:binding (schemas/pim/1/binding.xsd), or values.
  Params:  none.  Keys: those of bind.xsl.
  Provides: fp:bound-component, fp:port-interfaces, fp:data-ports, fp:port-problems.
  Errors:  BND002, BND004, BND005 (as data for f:fail-all), BND011.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:m="urn:robomda:xslt:mode"
    xmlns:t="urn:robomda:xslt:template"
    xmlns:mp="urn:robomda:xslt:mode:private"
    xmlns:err="http://www.w3.org/2005/xqt-errors"
    exclude-result-prefixes="#all">

  <!-- ============================================ components and ports -->
  <xsl:function name="fp:bound-component" as="element(pim:bound-component)">
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:variable name="r" as="element(pim:class)?" select="fp:realizing-class($c)"/>
    <xsl:variable name="h" as="xs:string?" select="fp:tag($r, 'AtomicCode', 'header')[normalize-space(.)]"/>
    <xsl:variable name="n" as="xs:string?" select="fp:tag($r, 'AtomicCode', 'cppName')[normalize-space(.)]"/>
    <xsl:variable name="cpp" as="xs:string?" select="($n, $r/@name)[1]"/>
    <xsl:if test="$r and not(normalize-space($cpp) and (every $part in tokenize(replace(string($cpp), '^::', ''), '::')
                             satisfies matches($part, '^[A-Za-z_][A-Za-z0-9_]*$')))">
      <xsl:sequence select="f:fail('BND011', string($r/@id), 'the realizing class of component '''
          || $c/@name || ''' has no usable C++ name (''' || string($cpp)
          || '''): name the class, or give its AtomicCode stereotype a cppName')"/>
    </xsl:if>
    <pim:bound-component component="{$c/@id}" name="{$c/@name}">
      <xsl:if test="$r">
        <xsl:attribute name="realization" select="$r/@id"/>
        <xsl:attribute name="realization-name" select="$r/@name"/>
        <xsl:attribute name="header" select="($h, $r/@name || '.hpp')[1]"/>
        <xsl:attribute name="header-source" select="if (exists($h)) then 'stereotype' else 'default'"/>
        <xsl:attribute name="cpp-name" select="($n, $r/@name)[1]"/>
        <xsl:attribute name="cpp-name-source" select="if (exists($n)) then 'stereotype' else 'name'"/>
      </xsl:if>
      <xsl:for-each select="$c/pim:port">
        <xsl:sequence select="fp:data-ports(., $c, $r)"/>
      </xsl:for-each>
    </pim:bound-component>
  </xsl:function>

  <!-- (interface id, direction) pairs of a port, flattened: id, dir, id, dir ... -->
  <xsl:function name="fp:port-interfaces" as="xs:string*">
    <xsl:param name="p" as="element(pim:port)"/>
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:param name="r" as="element(pim:class)?"/>
    <xsl:variable name="root" as="document-node()" select="root($p[1])"/>
    <xsl:variable name="t" as="element()?" select="key('fp:id', $p/@type, $root)"/>
    <xsl:variable name="conj" as="xs:boolean" select="$p/@conjugated = ('true', '1')"/>
    <xsl:sequence select="
        if ($p/pim:provided or $p/pim:required) then
          ($p/pim:provided ! (string(@interface), 'out'), $p/pim:required ! (string(@interface), 'in'))
        else if ($t/self::pim:interface) then
          (string($t/@id),
           if (($c, $r)/pim:requires/@interface = $t/@id) then 'in'
           else if (($c, $r)/pim:provides/@interface = $t/@id) then 'out'
           else if ($conj) then 'in' else 'out')
        else if ($t/self::pim:class) then
          ($t/pim:provides ! (string(@interface), if ($conj) then 'in' else 'out'),
           $t/pim:requires ! (string(@interface), if ($conj) then 'out' else 'in'))
        else if (fp:is-data-type($t)) then (string($t/@id), if ($conj) then 'in' else 'out')
        else if (empty($t) and $p/@primitive) then (string($p/@id), if ($conj) then 'in' else 'out')
        else ()"/>
  </xsl:function>

  <!-- true when port $p is typed by an interface that neither the
       component nor its realizing class provides or requires, and has no
       provided / required lists: fp:port-interfaces then guesses its
       direction from conjugation alone (rule APP006 says so) -->
  <xsl:function name="fp:direction-guessed" as="xs:boolean">
    <xsl:param name="p" as="element(pim:port)"/>
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:param name="r" as="element(pim:class)?"/>
    <xsl:variable name="t" as="element()?" select="key('fp:id', $p/@type, root($p))"/>
    <xsl:sequence select="not($p/pim:provided or $p/pim:required) and exists($t/self::pim:interface)
                          and not(($c, $r)/(pim:requires | pim:provides)/@interface = $t/@id)"/>
  </xsl:function>

  <!-- the problems of the data ports of port $p (BND002, BND004,
       BND005), as maps for f:fail-all -->
  <xsl:function name="fp:port-problems" as="map(*)*">
    <xsl:param name="p" as="element(pim:port)"/>
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:param name="r" as="element(pim:class)?"/>
    <xsl:variable name="root" as="document-node()" select="root($p[1])"/>
    <xsl:variable name="pairs" as="xs:string*" select="fp:port-interfaces($p, $c, $r)"/>
    <xsl:for-each select="1 to count($pairs) idiv 2">
      <xsl:variable name="i" as="element()?" select="key('fp:id', $pairs[2 * current() - 1], $root)"/>
      <xsl:variable name="data" as="element(pim:attribute)*" select="$i/pim:attribute"/>
      <xsl:choose>
        <xsl:when test="fp:is-data-type($i)"/>
        <xsl:when test="not($i/self::pim:interface)">
          <xsl:sequence select="map { 'code': 'BND002', 'id': string($p/@id), 'message': 'port ''' || $p/@name
              || ''' refers to ''' || $pairs[2 * current() - 1] || ''', which is not an interface' }"/>
        </xsl:when>
        <xsl:when test="empty($data)">
          <xsl:sequence select="map { 'code': 'BND004', 'id': string($i/@id), 'message': 'interface ''' || $i/@name
              || ''' (port ''' || $p/@name || ''') carries no datum: give it one attribute' }"/>
        </xsl:when>
        <xsl:when test="count($data) gt 1">
          <xsl:sequence select="map { 'code': 'BND005', 'id': string($i/@id), 'message': 'interface ''' || $i/@name
              || ''' (port ''' || $p/@name || ''') carries ' || count($data)
              || ' attributes (' || string-join($data/@name, ', ') || '): an interface carries exactly one datum' }"/>
        </xsl:when>
      </xsl:choose>
    </xsl:for-each>
  </xsl:function>

  <!-- a port's own type that is its data (a data type, primitive or
       enumeration of the model; the port itself for a library primitive) -->
  <xsl:function name="fp:is-data-type" as="xs:boolean">
    <xsl:param name="t" as="element()?"/>
    <xsl:sequence select="exists($t/(self::pim:datatype | self::pim:primitive | self::pim:enumeration
                                     | self::pim:port[@primitive]))"/>
  </xsl:function>

  <xsl:function name="fp:data-ports" as="element(pim:data-port)*">
    <xsl:param name="p" as="element(pim:port)"/>
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:param name="r" as="element(pim:class)?"/>
    <xsl:variable name="root" as="document-node()" select="root($p[1])"/>
    <xsl:sequence select="f:fail-all(fp:port-problems($p, $c, $r))"/>
    <xsl:variable name="pairs" as="xs:string*" select="fp:port-interfaces($p, $c, $r)"/>
    <xsl:variable name="n" as="xs:integer" select="count($pairs) idiv 2"/>
    <xsl:for-each select="1 to $n">
      <xsl:variable name="i" as="element()?" select="key('fp:id', $pairs[2 * current() - 1], $root)"/>
      <xsl:choose>
        <xsl:when test="fp:is-data-type($i)">
          <!-- a port typed by a data type carries that data itself: the
               type stands for the interface, the port for the datum -->
          <pim:data-port port="{$p/@id}" name="{f:cpp-identifier($p/@name)}"
                         port-name="{$p/@name}" direction="{$pairs[2 * current()]}"
                         interface="{$i/@id}" interface-name="{($i/self::pim:port/@type-name, $i/@name)[1]}"
                         datum="{$p/@id}" datum-name="{$p/@name}">
            <xsl:sequence select="$p/(@primitive, @type, @type-name, @upper)"/>
          </pim:data-port>
        </xsl:when>
        <xsl:otherwise>
          <xsl:variable name="data" as="element(pim:attribute)*" select="$i/pim:attribute"/>
          <pim:data-port port="{$p/@id}"
                         name="{f:cpp-identifier(if ($n eq 1) then $p/@name else $p/@name || '_' || $i/@name)}"
                         port-name="{$p/@name}" direction="{$pairs[2 * current()]}"
                         interface="{$i/@id}" interface-name="{$i/@name}"
                         datum="{$data/@id}" datum-name="{$data/@name}">
            <xsl:if test="fp:direction-guessed($p, $c, $r)">
              <xsl:attribute name="direction-source" select="'guessed'"/>
            </xsl:if>
            <xsl:sequence select="$data/(@primitive, @type, @type-name, @upper)"/>
          </pim:data-port>
        </xsl:otherwise>
      </xsl:choose>
    </xsl:for-each>
  </xsl:function>
</xsl:stylesheet>
