<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/import/dialects.xsl - what the modelling tools' own profiles mean
  (RobotML, Papyrus for Robotics, UML-RT, SysML, Papyrus Designer), read
  in each profile's terms: functions for application.xsl, stereotypes.xsl,
  platform.xsl, import.xsl and report.xsl.

  Reads:   the normalised XMI's stereotype applications (keys
           fp:stereotype-by-base, fp:dep-by-supplier of xmi-common.xsl), the
           model element as written (its top annotation), and the table
           dialects.xml beside this file: which profile, recognised by the
           namespace URI of its applications (never by file or tool name),
           says what. docs/profile.md, "Components drawn as classes".
  Writes:  attributes and children of the PIM elements the import makes
           (schemas/pim/1/pim.xsd):
           - pim:class/@component (true: a component; false: never one),
             @dialect, @managed, @parameters;
           - pim:port/@direction (or @direction-literal for a literal the
             table does not know; bind reports it, BND030), @buffer,
             @dialect, @runtime; the conjugation a profile's tag gives;
             pim:provided / pim:required of a service port by its kind;
           - pim:attribute/@direction of a flow property;
           - pim:interface/@pattern, @provided-direction, @dialect, @via of
             a communication pattern or a UML-RT message set, and its data
             or, for a request / response pattern, its operation
             (fp:pattern-datum, fp:pattern-operation, fp:message-data);
           - pim:stereotype/@means and pim:tag/@means (a tool's stereotype
             that stands for a robomda one: RobotML «Software» for
             «Activity»);
           - pim:application/@top (fp:top-name);
           - pim:node elements (execution environments) of a deployment
             plan's allocations (fp:allocation-nodes);
           - pim:deployment elements of a node that a SysML or Papyrus
             Designer «Allocate» targets, or an instance of it
             (fp:node-allocations, platform.xsl calls it per node).
  Params:  none.  Keys: fp:dialect-use (any application of a known
           dialect: one look-up says a model uses none), fp:slot-by-value,
           fp:abstraction-by-supplier, fp:planned-allocation.

  Errors:  none raised. Warnings: IMP120 a tag that means something only
           under a condition of its profile that does not hold; IMP121 a
           UML-RT message with no payload; IMP122 one with several
           parameters; IMP123 an allocation to a simulator or a middleware
           robomda has no target for; IMP124 an «Allocate» to what is no
           Node; IMP125 allocations to nodes in several deployment plans
           (none is read).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:array="http://www.w3.org/2005/xpath-functions/array"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:tp="urn:robomda:xslt:template:private"
    xmlns:d="urn:robomda:dialects"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:x="urn:robomda:import:xmi"
    exclude-result-prefixes="#all">

  <xsl:variable name="fp:dialects" as="element(d:dialect)*" select="doc('dialects.xml')/d:dialects/d:dialect"/>

  <!-- the dialect whose namespace URI pattern matches stereotype
       application $app -->
  <xsl:function name="fp:dialect" as="element(d:dialect)?">
    <xsl:param name="app" as="element()"/>
    <xsl:variable name="uri" as="xs:string" select="namespace-uri($app)"/>
    <xsl:sequence select="if ($uri = ('', 'urn:robomda:import:xmi')) then ()
                          else $fp:dialects[matches($uri, @uri)][1]"/>
  </xsl:function>

  <!-- the stereotype applications of a known dialect, all under one key
       value: whether a model uses any is one look-up -->
  <xsl:key name="fp:dialect-use" match="/x:XMI/*[not(namespace-uri() = ($U, $X))]"
      use="if (exists(fp:dialect(.))) then 'any' else ()"/>

  <!-- the stereotype applications on $e that a dialect knows, each with
       its dialect: map { 'app': the application, 'dialect': its d:dialect } -->
  <xsl:function name="fp:dialect-apps" as="map(*)*">
    <xsl:param name="e" as="element()"/>
    <!-- a model in no known dialect (most: the robomda profile, or none)
         asks no more than one look-up -->
    <xsl:sequence select="if (empty(key('fp:dialect-use', 'any', root($e)))) then ()
                          else key('fp:stereotype-by-base', fp:id($e), root($e))
                               ! (let $app := . return fp:dialect($app) ! map { 'app': $app, 'dialect': . })"/>
  </xsl:function>

  <!-- the rules of kind $kinds (element names of dialects.xml: data-port,
       conjugation ...) whose @stereotype is applied to $e, each with that
       application: map { 'app': the application, 'rule': the rule } -->
  <xsl:function name="fp:dialect-rules" as="map(*)*">
    <xsl:param name="e" as="element()"/>
    <xsl:param name="kinds" as="xs:string+"/>
    <xsl:sequence select="fp:dialect-apps($e)
                          ! (let $app := ?app
                             return ?dialect/*[local-name() = $kinds][@stereotype eq local-name($app)]
                                    ! map { 'app': $app, 'rule': . })"/>
  </xsl:function>

  <!-- true when the boolean tag of rule $r (fp:dialect-rules) is one of
       $values as written (true / 1, false / 0) -->
  <xsl:function name="fp:rule-tag-is" as="xs:boolean">
    <xsl:param name="r" as="map(*)"/>
    <xsl:param name="values" as="xs:string+"/>
    <xsl:sequence select="lower-case(string(fp:tag-literal($r?app, $r?rule/@tag))) = $values"/>
  </xsl:function>

  <!-- @component and @dialect of the pim:class made from class $e: true
       when a stereotype of a dialect's component list is applied to it,
       false when one of its not-component list is (none: bind's rule
       decides) -->
  <xsl:function name="fp:dialect-component" as="attribute()*">
    <xsl:param name="e" as="element()"/>
    <xsl:variable name="hit" as="map(*)?"
        select="fp:dialect-apps($e)[local-name(?app) = ?dialect/(d:component | d:not-component)/tokenize(@stereotypes)][1]"/>
    <xsl:if test="exists($hit)">
      <xsl:variable name="dialect" as="element(d:dialect)" select="$hit?dialect"/>
      <xsl:variable name="stereotype" as="xs:string" select="local-name($hit?app)"/>
      <xsl:variable name="component" as="xs:boolean" select="$stereotype = tokenize($dialect/d:component/@stereotypes)"/>
      <xsl:attribute name="component" select="$component"/>
      <xsl:attribute name="dialect" select="$dialect/@name || '::' || $stereotype"/>
      <xsl:if test="$component and exists($dialect/d:managed)">
        <xsl:attribute name="managed" select="'true'"/>
      </xsl:if>
      <xsl:if test="$stereotype = tokenize($dialect/d:parameters/@stereotypes)">
        <xsl:attribute name="parameters" select="'true'"/>
      </xsl:if>
    </xsl:if>
  </xsl:function>

  <!-- true when $e (a class or a property) is a component (a class) in
       its dialect, false when it is never one nor a part, () when no
       dialect says -->
  <xsl:function name="fp:dialect-says-component" as="xs:boolean?">
    <xsl:param name="e" as="element()"/>
    <xsl:sequence select="fp:dialect-component($e)[local-name() eq 'component'] ! xs:boolean(.)"/>
  </xsl:function>

  <!-- the attributes of the pim:port made from port $e that its dialect's
       data-port stereotype gives, or of the pim:attribute made from
       property $e that its flow-property stereotype gives (SysML): @direction
       (or @direction-literal for a literal the table does not know),
       @buffer, @dialect -->
  <xsl:function name="fp:dialect-port" as="attribute()*">
    <xsl:param name="e" as="element()"/>
    <xsl:variable name="hit" as="map(*)?" select="fp:dialect-rules($e, ('data-port', 'flow-property'))[1]"/>
    <xsl:if test="exists($hit)">
      <xsl:variable name="app" as="element()" select="$hit?app"/>
      <xsl:variable name="rule" as="element()" select="$hit?rule"/>
      <xsl:variable name="dialect" as="element(d:dialect)" select="$rule/.."/>
      <xsl:variable name="literal" as="xs:string" select="(fp:tag-literal($app, $rule/@tag), string($rule/@default))[1]"/>
      <xsl:variable name="direction" as="xs:string?"
          select="$rule/d:literal[lower-case(@name) eq lower-case($literal)][1]/@direction"/>
      <xsl:attribute name="{if (exists($direction)) then 'direction' else 'direction-literal'}"
          select="($direction, $literal)[1]"/>
      <xsl:attribute name="dialect" select="$dialect/@name || '::' || local-name($app)"/>
      <xsl:for-each select="$dialect/d:policy[@stereotype eq local-name($app)][1] ! fp:tag-literal($app, @tag)">
        <xsl:attribute name="buffer" select="."/>
      </xsl:for-each>
    </xsl:if>
  </xsl:function>

  <!-- the robomda stereotype application $app stands for in its dialect
       (a means element of dialects.xml: RobotML «Software» is an
       «Activity», its period and priority tags the same) -->
  <xsl:function name="fp:dialect-means" as="xs:string?">
    <xsl:param name="app" as="element()"/>
    <xsl:sequence select="fp:dialect($app)/d:means[@stereotype eq local-name($app)][1]/@robomda ! string(.)"/>
  </xsl:function>

  <!-- the robomda tag that tag $tag of application $app stands for (a
       tag element of its dialect's means element), when its condition
       (@when: a boolean tag of the same application, false when absent)
       holds; IMP120 when the tag is written and the condition does not
       hold: it is kept in the PIM and means nothing -->
  <xsl:function name="fp:dialect-tag-means" as="xs:string?">
    <xsl:param name="app" as="element()"/>
    <xsl:param name="tag" as="xs:string"/>
    <xsl:variable name="rule" as="element(d:tag)?"
        select="fp:dialect($app)/d:means[@stereotype eq local-name($app)][1]/d:tag[@name eq $tag][1]"/>
    <xsl:choose>
      <xsl:when test="empty($rule)"/>
      <xsl:when test="empty($rule/@when) or lower-case(string(fp:tag-literal($app, $rule/@when))) = ('true', '1')">
        <xsl:sequence select="string($rule/@means)"/>
      </xsl:when>
      <xsl:otherwise>
        <xsl:sequence select="f:warn('IMP120', fp:id($app), local-name($app) || ' of ' || string-join((fp:base-ids($app) ! fp:element($app, .))[1] ! fp:label(.), '')
            || ' gives ' || $tag || ' ' || fp:tag-literal($app, $tag) || ' but ' || $rule/@when
            || ' is not true: ' || $rule/../../@name || ' does not use the ' || $tag || ', so robomda does not either'
            || ' (set ' || $rule/@when || ' to true to use it)')"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <!-- the communication pattern interface $e binds, when its dialect's
       service-definition stereotype is applied to it: by the id its
       template binding's signature names (an href into the tool's
       library, or an id of the model), else by its name's prefix -->
  <xsl:function name="fp:pattern" as="element(d:pattern)?">
    <xsl:param name="e" as="element()"/>
    <xsl:variable name="rules" as="element(d:service-definition)*"
        select="fp:dialect-rules($e, 'service-definition') ! ?rule"/>
    <xsl:variable name="signature" as="xs:string*"
        select="$e/templateBinding/signature/@href ! replace(., '^.*#', ''), $e/templateBinding ! fp:ref-ids(., 'signature')"/>
    <xsl:sequence select="($rules/d:pattern[@signature = $signature],
                           $rules/d:pattern[starts-with($e/@name, @prefix)])[1]"/>
  </xsl:function>

  <!-- @pattern, @provided-direction and @dialect of the pim:interface made
       from interface $e (fp:pattern) -->
  <xsl:function name="fp:pattern-attributes" as="attribute()*">
    <xsl:param name="e" as="element()"/>
    <xsl:for-each select="fp:pattern($e)">
      <xsl:attribute name="pattern" select="@name"/>
      <xsl:if test="@provided">
        <xsl:attribute name="provided-direction" select="@provided"/>
      </xsl:if>
      <xsl:attribute name="dialect" select="../../@name || '::' || ../@stereotype"/>
    </xsl:for-each>
  </xsl:function>

  <!-- the datum of interface $e that binds a pattern carrying one (Push,
       Send): a pim:attribute for the first argument of its template
       binding (its parameterSubstitution's id; named and typed by the
       actual, fp:actual-typing: a ROS message sensor_msgs/Image is the
       datum Image) -->
  <xsl:function name="fp:pattern-datum" as="element(pim:attribute)?">
    <xsl:param name="e" as="element()"/>
    <xsl:param name="root" as="element()"/>
    <xsl:if test="exists(fp:pattern($e)/@provided)">
      <xsl:variable name="substitution" as="element()?" select="($e/templateBinding/parameterSubstitution)[1]"/>
      <xsl:variable name="typing" as="attribute()*" select="$substitution ! fp:actual-typing(.)"/>
      <xsl:if test="exists($typing)">
        <xsl:variable name="name" as="xs:string" select="tokenize($typing[name() eq 'type-name'], '/')[last()]"/>
        <pim:attribute id="{fp:id($substitution)}" name="{$name}" qualified-name="{fp:qname($e, $root)}::{$name}">
          <xsl:sequence select="$typing"/>
          <xsl:attribute name="visibility" select="'public'"/>
        </pim:attribute>
      </xsl:if>
    </xsl:if>
  </xsl:function>

  <!-- the operation of interface $e that binds a request / response
       pattern (d:pattern/@parameters, Papyrus for Robotics' Query): named
       after the interface without the pattern's prefix (Q_Detect: Detect,
       the template binding's id), its parameters the binding's arguments
       in order (each its parameterSubstitution's id, typed by
       fp:actual-typing): the first the request (in), the last the answer
       (return); () when an argument's type cannot be read (bind then says
       the interface carries nothing: BND004) -->
  <xsl:function name="fp:pattern-operation" as="element(pim:operation)?">
    <xsl:param name="e" as="element()"/>
    <xsl:param name="root" as="element()"/>
    <xsl:variable name="pattern" as="element(d:pattern)?" select="fp:pattern($e)"/>
    <xsl:variable name="names" as="xs:string*" select="tokenize($pattern/@parameters)"/>
    <xsl:variable name="substitutions" as="element()*" select="($e/templateBinding/parameterSubstitution)[position() le count($names)]"/>
    <xsl:variable name="typings" as="array(attribute()*)*" select="$substitutions ! array { fp:actual-typing(.) }"/>
    <xsl:if test="exists($names) and count($typings[array:size(.) gt 0]) eq count($names)">
      <xsl:variable name="name" as="xs:string"
          select="if (starts-with($e/@name, $pattern/@prefix) and string-length($e/@name) gt string-length($pattern/@prefix))
                  then substring($e/@name, string-length($pattern/@prefix) + 1) else string($e/@name)"/>
      <xsl:variable name="qname" as="xs:string" select="fp:qname($e, $root) || '::' || $name"/>
      <pim:operation id="{fp:id(($e/templateBinding)[1])}" name="{$name}" qualified-name="{$qname}"
          visibility="public" static="false" abstract="true" query="false">
        <xsl:for-each select="$names">
          <xsl:variable name="n" as="xs:integer" select="position()"/>
          <pim:parameter id="{fp:id($substitutions[$n])}" name="{.}" qualified-name="{$qname}::{.}">
            <xsl:sequence select="$typings[$n]?*"/>
            <xsl:attribute name="direction" select="if ($n eq count($names) and $n gt 1) then 'return' else 'in'"/>
          </pim:parameter>
        </xsl:for-each>
      </pim:operation>
    </xsl:if>
  </xsl:function>

  <!-- the pim:typed attributes of template argument $substitution: its
       actual, a data type of the model (an id), else the type a library's
       href names (fp:href-type); () when neither is there -->
  <xsl:function name="fp:actual-typing" as="attribute()*">
    <xsl:param name="substitution" as="element()"/>
    <xsl:variable name="actual" as="element()?" select="fp:targets($substitution, 'actual')[1]"/>
    <xsl:variable name="library" as="map(*)?"
        select="if (exists($actual)) then () else ($substitution/actual/@href)[1] ! fp:href-type(.)"/>
    <xsl:variable name="typing" as="element()">
      <typing>
        <xsl:if test="exists($library)">
          <xsl:attribute name="type-name" select="$library?name"/>
          <xsl:attribute name="type-library" select="$library?library"/>
          <xsl:for-each select="$library?kind">
            <xsl:attribute name="primitive" select="."/>
          </xsl:for-each>
        </xsl:if>
        <xsl:if test="exists($actual)">
          <xsl:attribute name="type" select="fp:id($actual)"/>
          <xsl:attribute name="type-name" select="$actual/@name"/>
          <xsl:attribute name="type-library" select="'local'"/>
          <xsl:if test="fp:is-primitive-like($actual)">
            <xsl:for-each select="fp:primitive-kind('local', $actual/@name)">
              <xsl:attribute name="primitive" select="."/>
            </xsl:for-each>
          </xsl:if>
        </xsl:if>
      </typing>
    </xsl:variable>
    <xsl:sequence select="$typing/@*"/>
  </xsl:function>

  <!-- the «Protocol» applications that make interface $e a message set:
       those of the collaborations that realize or use it, stereotyped as
       their dialect's protocol (d:messages/@protocol); fp:dialect-apps maps -->
  <xsl:function name="fp:message-protocols" as="map(*)*">
    <xsl:param name="e" as="element()"/>
    <xsl:sequence select="if (empty(key('fp:dialect-use', 'any', root($e)))) then ()
                          else key('fp:dep-by-supplier', fp:id($e), root($e))
                               ! fp:targets(., 'client')[@x:type eq 'Collaboration']
                               ! fp:dialect-apps(.)[?dialect/d:messages/@protocol = local-name(?app)]"/>
  </xsl:function>

  <!-- the dialect in which interface $e is a message set -->
  <xsl:function name="fp:message-dialect" as="element(d:dialect)?">
    <xsl:param name="e" as="element()"/>
    <xsl:sequence select="fp:message-protocols($e)[1]?dialect"/>
  </xsl:function>

  <!-- @pattern, @provided-direction, @dialect and @via (the «Protocol»
       applications) of the pim:interface made from message set $e: a port
       that provides it (its protocol realizes it) receives its messages -->
  <xsl:function name="fp:message-attributes" as="attribute()*">
    <xsl:param name="e" as="element()"/>
    <xsl:variable name="protocols" as="map(*)*" select="fp:message-protocols($e)"/>
    <xsl:for-each select="$protocols[1]?dialect">
      <xsl:variable name="protocol" as="xs:string" select="d:messages/@protocol"/>
      <xsl:attribute name="pattern" select="'Messages'"/>
      <xsl:attribute name="provided-direction" select="'in'"/>
      <xsl:attribute name="dialect" select="@name || '::' || $protocol"/>
      <xsl:attribute name="via" select="distinct-values($protocols[?dialect is current()] ! fp:id(?app))"/>
    </xsl:for-each>
  </xsl:function>

  <!-- the messages of message set $e, each a pim:attribute (its datum):
       the operation's id and name, typed by its first parameter that is
       no return (its payload); a message with no payload is a boolean
       signal (IMP121), one with several keeps the first (IMP122) -->
  <xsl:function name="fp:message-data" as="element(pim:attribute)*">
    <xsl:param name="e" as="element()"/>
    <xsl:param name="root" as="element()"/>
    <xsl:param name="href-types" as="map(*)"/>
    <xsl:for-each select="$e/ownedOperation">
      <xsl:variable name="payload" as="element()*" select="ownedParameter[not(@direction = 'return')]"/>
      <xsl:variable name="typed" as="attribute()*" select="$payload[1] ! fp:typed(., $href-types)"/>
      <xsl:if test="empty($typed[name() = ('type', 'type-name')])">
        <xsl:sequence select="f:warn('IMP121', fp:id(.), 'message ''' || @name || ''' of ' || fp:label($e)
            || (if (exists($payload)) then ' has a payload of no type robomda reads' else ' has no payload')
            || ': it is generated as a boolean signal (true on each message), a data port of its own')"/>
      </xsl:if>
      <xsl:if test="count($payload) gt 1">
        <xsl:sequence select="f:warn('IMP122', fp:id(.), 'message ''' || @name || ''' of ' || fp:label($e) || ' has '
            || count($payload) || ' parameters (' || string-join($payload/@name, ', ') || '): its payload is the first, '''
            || $payload[1]/@name || '''; give it one parameter of a data type holding them all')"/>
      </xsl:if>
      <pim:attribute id="{fp:id(.)}" name="{@name}" qualified-name="{fp:qname(., $root)}">
        <xsl:choose>
          <xsl:when test="exists($typed[name() = ('type', 'type-name')])">
            <xsl:sequence select="$typed"/>
          </xsl:when>
          <xsl:otherwise>
            <xsl:attribute name="type-name" select="'Boolean'"/>
            <xsl:attribute name="type-library" select="'uml'"/>
            <xsl:attribute name="primitive" select="'boolean'"/>
          </xsl:otherwise>
        </xsl:choose>
        <xsl:attribute name="visibility" select="'public'"/>
      </pim:attribute>
    </xsl:for-each>
  </xsl:function>

  <!-- true when port $e is conjugated by its dialect's conjugation tag
       (RSA-RTE's «RTPort» isConjugate) -->
  <xsl:function name="fp:dialect-conjugated" as="xs:boolean">
    <xsl:param name="e" as="element()"/>
    <xsl:sequence select="some $r in fp:dialect-rules($e, 'conjugation') satisfies fp:rule-tag-is($r, ('true', '1'))"/>
  </xsl:function>

  <!-- 'unwired' when port $e is unwired by its dialect's tag (UML-RT: an
       SAP or SPP), 'library' when it is typed by a protocol of its
       dialect's runtime library (Log, Timing ...): the runtime's service,
       no port of the generated system -->
  <xsl:function name="fp:runtime-port" as="xs:string?">
    <xsl:param name="e" as="element()"/>
    <xsl:variable name="unwired" as="xs:boolean"
        select="some $r in fp:dialect-rules($e, 'unwired') satisfies fp:rule-tag-is($r, ('false', '0'))"/>
    <xsl:sequence select="if ($unwired) then 'unwired'
        else if (some $h in $e/type/@href satisfies (some $p in $fp:dialects/d:runtime-library/@href satisfies matches($h, $p)))
        then 'library' else ()"/>
  </xsl:function>

  <!-- the allocation rule of the dialect of an «Allocate» on Abstraction $e -->
  <xsl:function name="fp:allocation-rule" as="element(d:allocation)?">
    <xsl:param name="e" as="element()"/>
    <xsl:sequence select="fp:dialect-rules($e, 'allocation')[1]?rule"/>
  </xsl:function>

  <!-- the node-allocation rule of Abstraction $e's dialect (SysML «Allocate») -->
  <xsl:function name="fp:node-allocation-rule" as="element(d:node-allocation)?">
    <xsl:param name="e" as="element()"/>
    <xsl:sequence select="fp:dialect-rules($e, 'node-allocation')[1]?rule"/>
  </xsl:function>

  <!-- true when $e is an Abstraction its dialect reads as an allocation
       (a deployment, or IMP123 / IMP124 saying why not) -->
  <xsl:function name="fp:is-allocation" as="xs:boolean">
    <xsl:param name="e" as="element()?"/>
    <xsl:sequence select="exists($e[@x:type eq 'Abstraction'])
                          and (exists(fp:allocation-rule($e)) or exists(fp:node-allocation-rule($e)))"/>
  </xsl:function>

  <!-- Abstractions by their suppliers, and by what a supplier instance or
       part is of (an allocation to an instance of a Node is to the Node) -->
  <xsl:key name="fp:abstraction-by-supplier" match="*[@x:type eq 'Abstraction']"
      use="fp:targets(., 'supplier') ! (fp:id(.), fp:node-of(.) ! fp:id(.))"/>

  <!-- the node an element stands for: itself, else the Node classifying an
       InstanceSpecification or typing a part -->
  <xsl:function name="fp:node-of" as="element()?">
    <xsl:param name="e" as="element()"/>
    <xsl:sequence select="(if ($e/@x:type = $node-metas) then $e
                           else if ($e/@x:type eq 'InstanceSpecification') then fp:targets($e, 'classifier')
                           else if ($e/@x:type eq 'Property') then fp:targets($e, 'type') else ())[@x:type = $node-metas][1]"/>
  </xsl:function>

  <!-- the deployment plan allocation $a belongs to: the nearest package
       stereotyped as its rule's @plan, else the package that owns it (a
       plan whose stereotype the tool did not write) -->

  <xsl:function name="fp:allocation-plan" as="element()?">
    <xsl:param name="a" as="element()"/>
    <xsl:variable name="plan" as="xs:string?" select="fp:node-allocation-rule($a)/@plan"/>
    <xsl:sequence select="if (empty($plan)) then ()
        else ($a/ancestor::*[@x:type = ('Package', 'Model')]
                 [key('fp:stereotype-by-base', fp:id(.), root(.))[local-name() eq $plan]][1],
              $a/ancestor::*[@x:type = ('Package', 'Model')][1])[1]"/>
  </xsl:function>

  <!-- the allocations to a node that belong to a deployment plan, under
       one key value -->
  <xsl:key name="fp:planned-allocation" match="*[@x:type eq 'Abstraction']"
      use="if (exists(fp:node-allocation-rule(.)/@plan) and exists(fp:targets(., 'supplier') ! fp:node-of(.))) then 'any' else ()"/>

  <!-- the deployment plans of the model's allocations, when there are
       several (alternatives: none is read, IMP125), else () -->
  <xsl:function name="fp:rival-plans" as="element()*">
    <xsl:param name="any" as="node()"/>
    <xsl:variable name="plans" as="element()*"
        select="if (empty(key('fp:dialect-use', 'any', root($any)))) then ()
                else (key('fp:planned-allocation', 'any', root($any)) ! fp:allocation-plan(.))/."/>
    <xsl:sequence select="if (count($plans) gt 1) then $plans else ()"/>
  </xsl:function>

  <!-- the pim:deployment of each «Allocate» (a node-allocation rule) to
       node $node: what it allocates runs there (not an allocation of a
       plan when there are $rival-plans: fp:rival-plans) -->
  <xsl:function name="fp:node-allocations" as="element(pim:deployment)*">
    <xsl:param name="node" as="element()"/>
    <xsl:param name="rival-plans" as="element()*"/>
    <xsl:for-each select="if (empty(key('fp:dialect-use', 'any', root($node)))) then ()
                          else key('fp:abstraction-by-supplier', fp:id($node), root($node))
                               [exists(fp:node-allocation-rule(.))]
                               [empty($rival-plans) or empty(fp:allocation-plan(.))]">
      <xsl:variable name="deployed" as="xs:string*"
          select="distinct-values(fp:targets(., 'client') ! (if (@x:type eq 'InstanceSpecification') then fp:allocated-element(.) else .) ! fp:id(.))"/>
      <xsl:if test="exists($deployed)">
        <pim:deployment id="{fp:id(.)}" name="{@name}" deployed="{$deployed}">
          <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="."/></xsl:call-template>
        </pim:deployment>
      </xsl:if>
    </xsl:for-each>
  </xsl:function>

  <!-- IMP125 when the allocations of plans are alternatives ($rival-plans:
       fp:rival-plans); IMP124 for the «Allocate»s (a node-allocation rule)
       to something that is no Node: a requirement, a block of hardware, a
       function ... -->
  <xsl:function name="fp:node-allocation-warnings" as="empty-sequence()">
    <xsl:param name="root" as="element()"/>
    <xsl:param name="rival-plans" as="element()*"/>
    <xsl:variable name="planned" as="element()*"
        select="if (empty($rival-plans)) then () else key('fp:planned-allocation', 'any', root($root))"/>
    <xsl:for-each select="$planned[1]">
      <xsl:sequence select="f:warn('IMP125', fp:id(.), 'the model''s allocations belong to ' || count($rival-plans)
          || ' deployment plans (' || string-join($rival-plans ! ('''' || @name || ''''), ', ') || '), alternatives of one another:'
          || ' robomda reads none of them, and the instances run where the model''s other deployments put them;'
          || ' keep one plan in the model you generate from (the allocations and their stereotypes: '
          || fp:with-stereotype-ids($planned) || ')')"/>
    </xsl:for-each>
    <!-- one warning per element allocated to: a model tracing its blocks to
         requirements allocates dozens -->
    <xsl:for-each-group select="if (empty(key('fp:dialect-use', 'any', root($root)))) then ()
                                else $root/descendant::*[@x:type eq 'Abstraction'][exists(fp:node-allocation-rule(.))]
                                     [empty(fp:targets(., 'supplier') ! fp:node-of(.))]"
                        group-by="string-join(fp:ref-ids(., 'supplier'), ' ')">
      <xsl:variable name="first" as="element()" select="current-group()[1]"/>
      <xsl:variable name="to" as="xs:string"
          select="string-join((fp:targets($first, 'supplier') ! (fp:meta(.) || ' ''' || @name || ''''),
                               fp:ref-ids($first, 'supplier')[empty(fp:element($first, .))]), ', ')"/>
      <xsl:variable name="n" as="xs:integer" select="count(current-group())"/>
      <xsl:sequence select="f:warn('IMP124', fp:id($first), $n || ' allocation' || (if ($n gt 1) then 's' else '')
          || ' («Allocate») of '
          || string-join(distinct-values(current-group() ! fp:targets(., 'client') ! ('''' || @name || '''')), ', ')
          || ' to ' || (if ($to) then $to else 'nothing') || ', which is no Node: robomda reads only an allocation to a Node'
          || ' (a Device, an ExecutionEnvironment) as a deployment there, so ' || (if ($n gt 1) then 'these stay' else 'it stays')
          || ' in the model only (a trace to a requirement, a function or a hardware block); to deploy, allocate to a Node'
          || ' (the allocations and their stereotypes: ' || fp:with-stereotype-ids(current-group()) || ')')"/>
    </xsl:for-each-group>
  </xsl:function>

  <!-- 'xmi:ids=' and the ids of $elements, each followed by its stereotype
       applications': how a warning names what it says is not read, so that
       nothing is left out in silence (report.xsl) -->
  <xsl:function name="fp:with-stereotype-ids" as="xs:string">
    <xsl:param name="elements" as="element()*"/>
    <xsl:sequence select="'xmi:ids=' || string-join($elements ! (fp:id(.), key('fp:stereotype-by-base', fp:id(.), root(.)) ! fp:id(.)), ',')"/>
  </xsl:function>

  <!-- slots by the instance their InstanceValue names -->
  <xsl:key name="fp:slot-by-value" match="slot" use="value ! fp:ref-ids(., 'instance')"/>

  <!-- the execution environments of a model's deployment plans (its
       dialect's allocation rule, xslt/import/dialects.xml): one pim:node
       per instance of a middleware robomda generates for that an
       «Allocate» targets, its deployments the allocated parts; IMP123 for
       each instance allocated to a simulator or another middleware -->
  <xsl:function name="fp:allocation-nodes" as="element(pim:node)*">
    <xsl:param name="root" as="element()"/>
    <xsl:variable name="allocations" as="element()*"
        select="if (empty(key('fp:dialect-use', 'any', root($root)))) then ()
                else $root/descendant::*[@x:type eq 'Abstraction'][exists(fp:allocation-rule(.))]"/>
    <xsl:for-each-group select="$allocations" group-by="string(fp:ref-ids(., 'supplier')[1])">
      <xsl:variable name="rule" as="element(d:allocation)" select="fp:allocation-rule(current-group()[1])"/>
      <xsl:variable name="target" as="element()?" select="fp:element(current-group()[1], current-grouping-key())"/>
      <xsl:variable name="apps" as="element()*"
          select="$target ! fp:targets(., 'classifier') ! key('fp:stereotype-by-base', fp:id(.), root(.))"/>
      <xsl:variable name="platform" as="element()?" select="$apps[local-name() eq $rule/@middleware][1]"/>
      <xsl:variable name="literal" as="xs:string?"
          select="$platform ! (fp:tag-literal(., $rule/@tag), string($rule/@default))[1]"/>
      <xsl:variable name="middleware" as="xs:string?"
          select="$rule/d:literal[upper-case(@name) eq upper-case(string($literal))][1]/@middleware"/>
      <xsl:variable name="allocated" as="element()*" select="current-group()"/>
      <xsl:choose>
        <xsl:when test="exists($middleware)">
          <pim:node id="{fp:id($target)}" name="{$target/@name}" qualified-name="{fp:qname($target, $root)}"
              kind="execution-environment" middleware="{$middleware}"
              dialect="{$rule/../@name}::{$rule/@middleware}">
            <xsl:for-each select="$allocated">
              <pim:deployment id="{fp:id(.)}" name="{@name}"
                  deployed="{fp:targets(., 'client') ! fp:allocated-element(.) ! fp:id(.)}">
                <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="."/></xsl:call-template>
              </pim:deployment>
            </xsl:for-each>
          </pim:node>
        </xsl:when>
        <xsl:otherwise>
          <xsl:variable name="what" as="xs:string"
              select="if (exists($apps[local-name() = tokenize($rule/@simulator)]))
                      then 'the simulator ''' || $target/@name || ''' (' || local-name($apps[local-name() = tokenize($rule/@simulator)][1]) || ')'
                      else if (exists($platform)) then 'the middleware ''' || $target/@name || ''' (' || $literal || ')'
                      else '''' || $target/@name || ''', which is no middleware'"/>
          <xsl:for-each select="$allocated">
            <xsl:sequence select="f:warn('IMP123', fp:id(.), fp:label(.) || ' allocates '
                || string-join(fp:targets(., 'client') ! ('''' || @name || ''''), ', ') || ' to ' || $what
                || ', for which robomda generates nothing: it is generated with the instances the model deploys on no'
                || ' middleware (a simulated sensor is generated as a component of its own, for its user class to fill in;'
                || ' the allocation and its stereotype: ' || fp:with-stereotype-ids(.) || ')')"/>
          </xsl:for-each>
        </xsl:otherwise>
      </xsl:choose>
    </xsl:for-each-group>
  </xsl:function>

  <!-- what an allocated InstanceSpecification $spec stands for: the part
       whose slot holds it (a deployment plan's instance of a part), else
       its classifier (the plan's main instance: the whole system) -->
  <xsl:function name="fp:allocated-element" as="element()?">
    <xsl:param name="spec" as="element()"/>
    <xsl:sequence select="(key('fp:slot-by-value', fp:id($spec), root($spec)) ! fp:targets(., 'definingFeature'),
                           fp:targets($spec, 'classifier'))[1]"/>
  </xsl:function>

  <!-- the name of the top of the system model $root names (a dialect's
       top annotation: Papyrus-RT's UMLRT_Default_top / top_name); $root is
       the model element as written (the normalised copy drops the
       eAnnotations of tools) -->
  <xsl:function name="fp:top-name" as="xs:string?">
    <xsl:param name="root" as="element()"/>
    <xsl:sequence select="($fp:dialects/d:top ! (let $rule := . return
                           $root/*:eAnnotations[@source eq $rule/@annotation]/*:details[@key eq $rule/@key]/@value))[1]
                          ! string(.)"/>
  </xsl:function>

  <!-- 'provided' or 'required' when port $e carries its dialect's
       service-port stereotype: the interface typing it is so -->
  <xsl:function name="fp:dialect-service-kind" as="xs:string?">
    <xsl:param name="e" as="element()"/>
    <xsl:sequence select="(fp:dialect-rules($e, 'service-port')
                           ! (let $rule := ?rule, $literal := (fp:tag-literal(?app, $rule/@tag), string($rule/@default))[1]
                              return ($rule/d:literal[lower-case(@name) eq lower-case($literal)]/@kind, string($rule/@default))[1]))[1]"/>
  </xsl:function>

  <!-- the value of tag $tag of application $app as written: an attribute,
       else a child's text; an enumeration literal given by reference
       (an id of the model, or an href ending in #Name) is its name -->
  <xsl:function name="fp:tag-literal" as="xs:string?">
    <xsl:param name="app" as="element()"/>
    <xsl:param name="tag" as="xs:string"/>
    <xsl:variable name="value" as="xs:string?"
        select="($app/@*[local-name() eq $tag][namespace-uri() eq ''], $app/*[local-name() eq $tag])[1]
                ! normalize-space(if (@href) then replace(@href, '^.*#', '') else string(.))"/>
    <xsl:sequence select="$value[. ne '']"/>
  </xsl:function>
</xsl:stylesheet>
