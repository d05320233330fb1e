<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/diagrams/diagrams-components.xsl - the component view of a model,
  as PlantUML (diagrams/<model>-components.puml).

  Reads:   the bound PIM (urn:robomda:pim:1): pim:component with its ports,
           parts and connectors; pim:binding (bound components, instances,
           composite instances, connections, calls). Keys of main.xsl.
  Writes:  the text of one PlantUML component diagram:
           - each top composite (a component with parts that types no part)
             as a box with its own ports, and inside it its parts, a part
             typed by a composite drawn open in turn (its ports, parts,
             connectors), at any depth; a part typed by no component as a
             plain box;
           - each other component that types no part as a box with its ports;
           - a port as a circle labelled "name : data type", stereotyped
             <<out>> / <<in>> (data written / read, from the binding's data
             ports where the component is bound, else from what the port's
             interface is to the component, else its conjugation),
             <<provided>> / <<required>> (operations), <<in/out>> (both);
           - assembly connectors as arrows from the writing (or calling)
             port to the reading (or providing) one, delegations dashed (grey)
             between the composite's own port and its part's, in the way the
             data or the calls flow; a legend of what it shows; where the model connects
             by interfaces (binding connections-from="interfaces"), the
             binding's connections and calls between the instances' ports.
  Params:  none.
  Errors:  none.
  Provides: fp:component-view($model).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:key name="fp:composite-instance" match="pim:binding/pim:composite-instance" use="@path"/>

  <xsl:function name="fp:component-view" as="xs:string">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:variable name="components" as="element(pim:component)*" select="$model/pim:application//pim:component"/>
    <xsl:variable name="unused" as="element(pim:component)*" select="$components[empty(key('fp:part-by-type', @id))]"/>
    <xsl:variable name="tops" as="element(pim:component)*" select="$unused[pim:part]"/>
    <xsl:variable name="alone" as="element(pim:component)*" select="$unused[empty(pim:part)]"/>
    <xsl:sequence select="fp:lines((
        fp:puml-open('Components of model ''' || $model/@name || '''', $fp:components-xsl, 'model ''' || $model/@name || ''''),
        'left to right direction',
        'skinparam interface {', '  BackgroundColor&lt;&lt;in&gt;&gt; White', '  BackgroundColor&lt;&lt;required&gt;&gt; White', '}',
        ($tops, $alone) ! fp:component-box(., fp:puml-quoted(@name), (string(@id)), ()),
        if (empty($components)) then 'note as N_empty' || '&#10;  The model has no component.&#10;end note' else (),
        $tops ! fp:connector-edges(., (string(@id)), ()),
        if ($model/pim:binding/@connections-from = 'interfaces') then fp:binding-edges($model/pim:binding) else (),
        fp:legend($model),
        fp:puml-close()))"/>
  </xsl:function>

  <!-- what the circles and arrows mean, the lines of what the view shows -->
  <xsl:function name="fp:legend" as="xs:string*">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:variable name="lines" as="xs:string*" select="
        if ($model/pim:application//pim:component/pim:port) then (
          '  port: filled circle «out» writes its data, «provided» offers operations;',
          '  white circle «in» reads, «required» calls them') else (),
        if ($model/pim:application//pim:connector[not(@kind = 'delegation')] or $model/pim:binding/(pim:connection | pim:call))
        then '  solid arrow: connector, from the writer (caller) to the reader (provider)' else (),
        if ($model/pim:application//pim:connector[@kind = 'delegation'])
        then '  grey dashed arrow: delegation between a composite''s own port and its part''s' else ()"/>
    <xsl:sequence select="if (empty($lines)) then () else ('legend right', $lines, 'endlegend')"/>
  </xsl:function>

  <!-- the box of component $c at the place $path (xmi:ids: the top
       component, then each part down to this one), labelled $label; open
       (ports, parts) unless $c is one of $seen (its own ancestors) -->
  <xsl:function name="fp:component-box" as="xs:string*">
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:param name="label" as="xs:string"/>
    <xsl:param name="path" as="xs:string+"/>
    <xsl:param name="seen" as="xs:string*"/>
    <xsl:variable name="alias" as="xs:string" select="fp:puml-alias('c', $path)"/>
    <xsl:variable name="open" as="xs:boolean" select="not($c/@id = $seen)"/>
    <xsl:variable name="inside" as="xs:string*" select="if (not($open)) then () else (
        $c/pim:port ! ('() ' || fp:puml-quoted(@name || fp:port-type(., $c)) || ' &lt;&lt;' || fp:port-kind(., $c) || '&gt;&gt; as '
                       || fp:puml-alias('p', ($path, @id))),
        $c/pim:part ! (let $type := key('fp:id', @type)[self::pim:component]
                       return if ($type) then fp:component-box($type, fp:puml-quoted(@name || ' : ' || $type/@name || fp:multiplicity(.)),
                                                               ($path, string(@id)), ($seen, string($c/@id)))
                       (: a part typed by no component of the model: a plain box, its type as written :)
                       else 'rectangle ' || fp:puml-quoted(@name || (@type-name, @primitive)[1] ! (' : ' || .) || fp:multiplicity(.))
                            || ' as ' || fp:puml-alias('c', ($path, string(@id)))))"/>
    <xsl:variable name="head" as="xs:string" select="'component ' || $label
        || (if ($c/pim:part) then ' &lt;&lt;composite&gt;&gt;' else '') || ' as ' || $alias"/>
    <xsl:sequence select="if (empty($inside)) then $head else ($head || ' {', fp:indent(2, $inside), '}')"/>
  </xsl:function>

  <xsl:function name="fp:multiplicity" as="xs:string">
    <xsl:param name="part" as="element(pim:part)"/>
    <xsl:sequence select="if (($part/@lower, '1')[1] = '1' and ($part/@upper, '1')[1] = '1') then ''
                          else ' [' || ($part/@lower, '1')[1] || '..' || ($part/@upper, '1')[1] || ']'"/>
  </xsl:function>

  <!-- " : type" of a port: its data types (bound data ports), interfaces
       (service ports), else its own type; "" when it has none -->
  <xsl:function name="fp:port-type" as="xs:string">
    <xsl:param name="port" as="element(pim:port)"/>
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:variable name="bound" as="element()*"
        select="key('fp:bc', $c/@id, root($c))/(pim:data-port | pim:service-port)[@port = $port/@id]"/>
    <xsl:variable name="types" as="xs:string*" select="distinct-values(
        if ($bound) then $bound/(if (self::pim:data-port) then (@type-name, @primitive, @datum-name)[1] else @interface-name)
        else ($port/@type-name, $port/@primitive)[1])"/>
    <xsl:sequence select="if (empty($types)) then '' else ' : ' || string-join($types, ', ')"/>
  </xsl:function>

  <!-- in, out, provided, required or in/out (see the header) -->
  <xsl:function name="fp:port-kind" as="xs:string">
    <xsl:param name="port" as="element(pim:port)"/>
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:variable name="bound" as="element()*"
        select="key('fp:bc', $c/@id, root($c))/(pim:data-port | pim:service-port)[@port = $port/@id]"/>
    <xsl:variable name="type" as="element()?" select="key('fp:id', $port/@type, root($port))"/>
    <xsl:variable name="service" as="xs:boolean"
        select="exists($bound/self::pim:service-port) or exists($type/self::pim:interface[pim:operation][empty(pim:attribute)])"/>
    <xsl:variable name="provides" as="xs:boolean" select="exists($port/pim:provided) or $c/pim:provides/@interface = $type/@id"/>
    <xsl:variable name="requires" as="xs:boolean" select="exists($port/pim:required) or $c/pim:requires/@interface = $type/@id"/>
    <xsl:variable name="ways" as="xs:string*" select="distinct-values(
        if ($bound) then $bound/(@direction, if (@role = 'provided') then 'out' else 'in')[1]
        else if ($provides or $requires) then ('out'[$provides], 'in'[$requires])
        else if ($port/@conjugated = ('true', '1')) then 'in' else 'out')"/>
    <xsl:sequence select="if (count($ways) gt 1) then 'in/out'
                          else if ($service) then (if ($ways = 'out') then 'provided' else 'required')
                          else $ways"/>
  </xsl:function>

  <!-- the connectors of composite $c at $path, and of the composites
       drawn open inside it -->
  <xsl:function name="fp:connector-edges" as="xs:string*">
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:param name="path" as="xs:string+"/>
    <xsl:param name="seen" as="xs:string*"/>
    <xsl:if test="not($c/@id = $seen)">
      <xsl:for-each select="$c/pim:connector[count(pim:end) ge 2]">
        <xsl:variable name="ends" as="element(pim:end)+" select="pim:end"/>
        <xsl:variable name="aliases" as="xs:string+" select="$ends ! fp:end-alias(., $c, $path, $seen)"/>
        <xsl:variable name="kinds" as="xs:string+" select="$ends ! fp:end-kind(., $c)"/>
        <xsl:variable name="delegation" as="xs:boolean" select="@kind = 'delegation' or exists($ends[empty(@part)])"/>
        <!-- the source: the writing / calling end; of a delegation, the
             composite's own port when it reads or offers operations, else
             the part's port (what flows, flows out) -->
        <xsl:variable name="outer" as="xs:integer?" select="index-of($ends ! empty(@part), true())[1]"/>
        <xsl:variable name="from" as="xs:integer" select="(
            if ($delegation and exists($outer)) then (if ($kinds[$outer] = ('out', 'required')) then (1 to count($ends))[. ne $outer][1] else $outer)
            else index-of($kinds ! (. = ('out', 'required')), true()), 1)[1]"/>
        <xsl:variable name="label" as="xs:string" select="if (normalize-space(@name)) then ' : ' || fp:puml-quoted(@name) else ''"/>
        <xsl:for-each select="(1 to count($ends))[. ne $from]">
          <xsl:sequence select="$aliases[$from] || (if ($delegation) then ' .[#7f7f7f].&gt; ' else ' --&gt; ') || $aliases[current()] || $label"/>
        </xsl:for-each>
      </xsl:for-each>
      <xsl:for-each select="$c/pim:part">
        <xsl:sequence select="key('fp:id', @type)[self::pim:component]
                              ! fp:connector-edges(., ($path, string(current()/@id)), ($seen, string($c/@id)))"/>
      </xsl:for-each>
    </xsl:if>
  </xsl:function>

  <!-- what a connector end is drawn at: the port of the part (or of the
       composite itself) where that port is drawn, else the part's box -->
  <xsl:function name="fp:end-alias" as="xs:string">
    <xsl:param name="end" as="element(pim:end)"/>
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:param name="path" as="xs:string+"/>
    <xsl:param name="seen" as="xs:string*"/>
    <!-- by key: a composite of N parts has N connectors, so a scan of its parts per end grows as N x N -->
    <xsl:variable name="part" as="element(pim:part)?" select="fp:part-of($end, $c)"/>
    <xsl:variable name="owner" as="element()?" select="if ($end/@part) then key('fp:id', $part/@type, root($end))[self::pim:component] else $c"/>
    <xsl:variable name="at" as="xs:string+" select="if ($part) then ($path, string($part/@id)) else $path"/>
    <xsl:sequence select="
        if ($owner/pim:port[@id = $end/@role] and not($part and ($owner/@id = ($seen, $c/@id)))) then fp:puml-alias('p', ($at, $end/@role))
        else if ($part) then fp:puml-alias('c', $at)
        else fp:puml-alias('c', $path)"/>
  </xsl:function>

  <!-- the part of composite $c that connector end $end names -->
  <xsl:function name="fp:part-of" as="element(pim:part)*">
    <xsl:param name="end" as="element(pim:end)"/>
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:sequence select="key('fp:id', $end/@part, root($end))[self::pim:part][.. is $c]"/>
  </xsl:function>

  <xsl:function name="fp:end-kind" as="xs:string">
    <xsl:param name="end" as="element(pim:end)"/>
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:variable name="owner" as="element()?"
        select="if ($end/@part) then key('fp:id', fp:part-of($end, $c)/@type, root($end))[self::pim:component] else $c"/>
    <xsl:sequence select="($owner/pim:port[@id = $end/@role] ! fp:port-kind(., $owner), '')[1]"/>
  </xsl:function>

  <!-- connections and calls found from interfaces: between the ports of
       the instances, where each is drawn -->
  <xsl:function name="fp:binding-edges" as="xs:string*">
    <xsl:param name="binding" as="element(pim:binding)"/>
    <xsl:for-each select="$binding/(pim:connection | pim:call)">
      <xsl:variable name="label" as="xs:string" select="' : ' || fp:puml-quoted(@name)"/>
      <xsl:for-each select="pim:writer | pim:caller">
        <xsl:variable name="from" as="xs:string" select="fp:instance-port-alias(.)"/>
        <xsl:for-each select="../(pim:reader | pim:provider)">
          <xsl:sequence select="$from || ' --&gt; ' || fp:instance-port-alias(.) || $label"/>
        </xsl:for-each>
      </xsl:for-each>
    </xsl:for-each>
  </xsl:function>

  <!-- the alias of a connection end's port: the instance's place is its
       top composite and the parts down to it (a component instance of its
       own: the component) -->
  <xsl:function name="fp:instance-port-alias" as="xs:string">
    <xsl:param name="end" as="element()"/>
    <xsl:variable name="instance" as="element(pim:instance)?" select="key('fp:instance-by-name', $end/@instance, root($end))"/>
    <xsl:variable name="parents" as="xs:string*" select="tokenize(string($instance/@parent), '\.')"/>
    <xsl:variable name="path" as="xs:string+" select="
        if ($instance/@composite) then
          (string($instance/@composite),
           (for $i in 1 to count($parents)
            return string(key('fp:composite-instance', string-join($parents[position() le $i], '.'), root($end))/@xmi-id)),
           string($instance/@xmi-id))
        else string(($instance/@component, $end/@instance)[1])"/>
    <xsl:sequence select="fp:puml-alias('p', ($path, $end/@port))"/>
  </xsl:function>
</xsl:stylesheet>
